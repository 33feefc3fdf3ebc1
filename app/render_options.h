#pragma once
/// \file
/// The options of `trimlab render`, parsed without touching the scene or OpenGL so that
/// bad arguments fail fast with one line.

#include "trim/trim_settings.h"
#include "view/camera.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <variant>

namespace trimlab::app {

enum class Backend { KPlus, Reference };

struct RenderOptions {
    std::string source;         ///< a mesh file or "demo:NAME"
    TrimSettings trim;          ///< rule (or trimming off) and clip plane
    bool ruleGiven = false;     ///< --rule was on the command line (not the default)
    std::optional<Camera> camera; ///< --camera; otherwise fitted to the scene like the GUI
    int width = 1024;
    int height = 768;
    int k = 16;
    Backend backend = Backend::KPlus;
    unsigned threads = 0;       ///< reference backend; 0 = all cores
    int repeat = 1;             ///< frames rendered; times reported as the median
    QString output;             ///< -o, PNG
    QString depthOutput;        ///< --depth, PFM
    QString idsOutput;          ///< --ids, 16-bit PNG
};

/// Parses the arguments after the verb ("render"). Returns the options or a one-line
/// error message. `helpText` receives the usage text when --help was given (then the
/// returned error is empty).
[[nodiscard]] std::variant<RenderOptions, QString> parseRenderOptions(const QStringList& arguments, QString* helpText);

} // namespace trimlab::app
