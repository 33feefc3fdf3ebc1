#pragma once
/// \file
/// Compiles and links every GLSL program TrimLab uses, from the embedded shader files.
/// A compile or link failure throws ShaderBuildError with the info log and the numbered
/// source around each reported line; a link result is never ignored.

#include "render/gl/gl_functions.h"

#include <QHash>
#include <QString>
#include <QStringList>

#include <vector>

namespace trimlab::render {

/// One set of defines a program is used with, and the OpenGL extension it needs
/// (nullptr: none). The whole-library test builds every variant the test context
/// supports and checks all of them with glslangValidator.
struct ProgramVariant {
    QStringList defines;
    const char* requiredExtension = nullptr;
};

/// A program: its name and the shader files of its stages (the stage follows from the
/// extension: .vert, .frag, .comp).
struct ProgramDescription {
    QString name;
    QStringList files;
    std::vector<ProgramVariant> variants; ///< at least one
};

/// The catalog of every program in the application.
[[nodiscard]] const std::vector<ProgramDescription>& programCatalog();

class ShaderLibrary {
public:
    /// Needs the GL context that will use the programs to be current, now and at destruction.
    explicit ShaderLibrary(GlFunctions& gl);
    ~ShaderLibrary();
    ShaderLibrary(const ShaderLibrary&) = delete;
    ShaderLibrary& operator=(const ShaderLibrary&) = delete;

    /// The linked program `name` built with `defines` (compiled on first request, then
    /// cached). Throws ShaderBuildError.
    GLuint program(const QString& name, const QStringList& defines = {});

private:
    GLuint build(const ProgramDescription& description, const QStringList& defines);
    GLuint compileStage(const QString& file, const QStringList& defines);

    GlFunctions& m_gl;
    QHash<QString, GLuint> m_programs;
};

} // namespace trimlab::render
