#pragma once
/// \file
/// What the current OpenGL context offers, and whether it is enough for TrimLab.

#include <QSet>
#include <QString>

#include <optional>

class QOpenGLContext;

namespace trimlab::render {

struct GlCapabilities {
    int majorVersion = 0;
    int minorVersion = 0;
    bool coreProfile = false;
    QString vendor;
    QString renderer;
    QString versionString;
    QString glslVersion;
    /// GL_ARB_fragment_shader_interlock: lets the k⁺-buffer replace its spin-lock.
    bool fragmentShaderInterlock = false;
    qint64 maxShaderStorageBlockBytes = 0;
    int maxTextureSize = 0;
    int maxArrayTextureLayers = 0;
    int maxFragmentImageUniforms = 0;
    QSet<QByteArray> extensions;

    [[nodiscard]] bool hasExtension(const char* name) const { return extensions.contains(QByteArray(name)); }

    /// "llvmpipe (LLVM 15.0.6, 256 bits) — OpenGL 4.5 (Core Profile) Mesa 22.3.6": for the
    /// About box, benchmark headers and logs.
    [[nodiscard]] QString summary() const;
};

/// Queries the current context (which must be current).
[[nodiscard]] GlCapabilities queryCapabilities(QOpenGLContext& context);

/// nullopt when the context can run TrimLab; otherwise a message naming every missing
/// requirement and what to do (e.g. update the driver, run under Xvfb with Mesa).
[[nodiscard]] std::optional<QString> missingRequirements(const GlCapabilities& caps);

} // namespace trimlab::render
