#pragma once
/// \file
/// The options of `trimlab bench`, parsed before any scene is loaded or any OpenGL context
/// exists, so that bad arguments fail fast with one line (exit code 2).

#include "app/scene_composition.h"
#include "render/mfr/fragment_method.h"
#include "core/trim/trim_settings.h"

#include <QSize>
#include <QString>
#include <QStringList>

#include <string>
#include <variant>
#include <vector>

namespace trimlab::app {

/// --locks: which per-pixel critical section the k⁺-buffer family is measured with.
enum class BenchLocks {
    Auto,     ///< fragment shader interlock where the driver has it, else the spin-lock
    SpinLock, ///< always the spin-lock
    Both,     ///< as Auto, and where that used interlock, the same method again with the spin-lock
};

struct BenchOptions {
    /// --scenes: catalog names (bench_scenes.h), demo:NAME or mesh files; empty: the catalog.
    QStringList scenes;
    /// --size: one or more frame sizes. Default 1024x768.
    std::vector<QSize> sizes{QSize(1024, 768)};
    /// --methods: the methods to run, in menu order; default every method of this build.
    std::vector<render::FragmentMethodKind> methods;
    /// --k and --shared-counters (other parameters keep their defaults).
    render::MethodParameters parameters;
    int repeat = 5;          ///< --repeat: timed frames per view
    int views = 8;           ///< --views: cameras on the orbit around each scene
    unsigned threads = 0;    ///< --threads of the CPU reference; 0 = all cores
    BenchLocks locks = BenchLocks::Auto;
    QString jsonOutput;      ///< --json FILE
    QString dataDirectory;   ///< --data DIR: where the catalog's mesh files are
    /// Positional sources: one more scene made of them (object ids across the sources in
    /// order), measured after the --scenes (alone when --scenes is not given), drawn with
    /// `composedTrim` (--rule, --csg, --object-rule) and `objectTransforms`.
    std::vector<std::string> sources;
    TrimSettings composedTrim;
    std::vector<ObjectTransformOption> objectTransforms;
};

/// Parses the arguments after "bench". Returns the options or a one-line error;
/// `helpText` receives the usage text when --help was given (the returned error is then
/// empty).
[[nodiscard]] std::variant<BenchOptions, QString> parseBenchOptions(const QStringList& arguments, QString* helpText);

} // namespace trimlab::app
