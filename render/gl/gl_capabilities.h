#pragma once
/// \file
/// What the current OpenGL context offers, and whether it is enough for TrimLab.

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
    /// GL_ARB_fragment_shader_interlock, GL_NV_fragment_shader_interlock or
    /// GL_INTEL_fragment_shader_ordering: lets the k⁺-buffer replace its spin-lock.
    bool fragmentShaderInterlock = false;
    qint64 maxShaderStorageBlockBytes = 0;
    int maxTextureSize = 0;
    int maxArrayTextureLayers = 0;
    int maxFragmentImageUniforms = 0;

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
