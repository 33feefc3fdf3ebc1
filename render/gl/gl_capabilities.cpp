#include "render/gl/gl_capabilities.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QStringList>

namespace trimlab::render {

namespace {

// Image units the k⁺-buffer store pass binds at once (counter, semaphore, winding,
// overflow flag, fragment array).
constexpr int kRequiredFragmentImageUnits = 5;

QString glString(QOpenGLFunctions& f, GLenum name)
{
    const auto* s = reinterpret_cast<const char*>(f.glGetString(name));
    return s ? QString::fromLatin1(s) : QString();
}

} // namespace

QString GlCapabilities::summary() const
{
    return QStringLiteral("%1 — OpenGL %2 (GLSL %3)").arg(renderer, versionString, glslVersion);
}

GlCapabilities queryCapabilities(QOpenGLContext& context)
{
    GlCapabilities caps;
    const QSurfaceFormat format = context.format();
    caps.majorVersion = format.majorVersion();
    caps.minorVersion = format.minorVersion();
    caps.coreProfile = format.profile() == QSurfaceFormat::CoreProfile;
    QOpenGLFunctions& f = *context.functions();
    caps.vendor = glString(f, GL_VENDOR);
    caps.renderer = glString(f, GL_RENDERER);
    caps.versionString = glString(f, GL_VERSION);
    caps.glslVersion = glString(f, GL_SHADING_LANGUAGE_VERSION);
    caps.extensions = context.extensions();
    caps.fragmentShaderInterlock = caps.hasExtension("GL_ARB_fragment_shader_interlock");
    if (caps.majorVersion > 4 || (caps.majorVersion == 4 && caps.minorVersion >= 3)) {
        GLint value = 0;
        f.glGetIntegerv(0x90DE /* GL_MAX_SHADER_STORAGE_BLOCK_SIZE */, &value);
        caps.maxShaderStorageBlockBytes = static_cast<unsigned>(value);
        f.glGetIntegerv(0x90CE /* GL_MAX_FRAGMENT_IMAGE_UNIFORMS */, &caps.maxFragmentImageUniforms);
    }
    f.glGetIntegerv(GL_MAX_TEXTURE_SIZE, &caps.maxTextureSize);
    f.glGetIntegerv(0x88FF /* GL_MAX_ARRAY_TEXTURE_LAYERS */, &caps.maxArrayTextureLayers);
    return caps;
}

std::optional<QString> missingRequirements(const GlCapabilities& caps)
{
    QStringList missing;
    if (caps.majorVersion < 4 || (caps.majorVersion == 4 && caps.minorVersion < 3))
        missing << QStringLiteral("OpenGL 4.3 (this context is %1.%2)").arg(caps.majorVersion).arg(caps.minorVersion);
    else if (caps.maxFragmentImageUniforms < kRequiredFragmentImageUnits)
        missing << QStringLiteral("%1 image units in fragment shaders (the driver offers %2)")
                       .arg(kRequiredFragmentImageUnits)
                       .arg(caps.maxFragmentImageUniforms);
    if (missing.isEmpty())
        return std::nullopt;
    return QStringLiteral("TrimLab needs %1, but the OpenGL driver (%2) does not provide it. Update the graphics "
                          "driver, or use Mesa's llvmpipe (package libgl1-mesa-dri; headless: run under xvfb-run).")
        .arg(missing.join(QStringLiteral(" and ")),
             caps.renderer.isEmpty() ? QStringLiteral("unknown") : caps.renderer);
}

} // namespace trimlab::render
