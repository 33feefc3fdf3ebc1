#pragma once
/// \file
/// Turns a shader file from the embedded resources into the text handed to the GL
/// compiler: `#define` lines after `#version` — first every binding point
/// (bindings.h: the one source of those numbers), then the variant's —, `#include
/// "common/x.glsl"` expanded once per file. No OpenGL needed, so the same text can also
/// be checked by glslangValidator.

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <vector>

namespace trimlab::render {

/// Where one line of the assembled text came from.
struct SourceOrigin {
    QString file;
    int line = 0; ///< 1-based line in `file`; 0 for injected #define lines
};

struct AssembledShader {
    QString file;                      ///< e.g. "kplus_store.frag"
    QByteArray text;                   ///< the complete source handed to glShaderSource
    std::vector<SourceOrigin> origins; ///< origins[i] is line i+1 of `text`

    /// The assembled lines `line-context … line+context`, numbered, each with its origin,
    /// the reported line marked ">>". For compiler error reports.
    [[nodiscard]] QString excerpt(int line, int context = 3) const;
};

/// Root of the embedded shader files (a Qt resource path, ":/shaders").
[[nodiscard]] QString shaderResourceRoot();

/// Assembles `file` (relative to shaderResourceRoot()) with the binding defines and
/// `defines`, "NAME" or "NAME VALUE" strings. Throws ShaderBuildError when a file or include is missing or the
/// file does not start with a #version line.
[[nodiscard]] AssembledShader assembleShader(const QString& file, const QStringList& defines = {});

/// Every shader file embedded in the resources (relative paths), for whole-library checks.
[[nodiscard]] QStringList embeddedShaderFiles();

} // namespace trimlab::render
