#include "render/gl/offscreen_gl_context.h"

#include "render/gl/gl_debug_log.h"
#include "render/gl/gl_error.h"
#include "render/gl/wide_vector_state.h"

#include <QOpenGLDebugLogger>

#include <QGuiApplication>

namespace trimlab::render {

QSurfaceFormat OffscreenGlContext::requestedFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    // Ask to be told about GPU resets (gl/context_reset.h); where the platform ignores
    // the request (Qt 6.4 on GLX) the context is the same as without it.
    format.setOption(QSurfaceFormat::ResetNotification);
    return withDebugRequest(format);
}

OffscreenGlContext::OffscreenGlContext()
{
    if (!qGuiApp)
        throw GlUnavailableError("An OpenGL context needs a QGuiApplication (programming error in the caller).");
    m_context = std::make_unique<QOpenGLContext>();
    m_context->setFormat(requestedFormat());
    if (!m_context->create())
        throw GlUnavailableError(
            "Could not create an OpenGL 4.3 core context. Headless machines need an X server: run the command "
            "under 'xvfb-run -a' (packages xvfb, xauth, libgl1-mesa-dri).");
    m_surface = std::make_unique<QOffscreenSurface>();
    m_surface->setFormat(m_context->format());
    m_surface->create();
    if (!m_surface->isValid() || !m_context->makeCurrent(m_surface.get()))
        throw GlUnavailableError("Could not make the offscreen OpenGL context current (is an X display available?).");
    m_debugLog = startGlDebugLog(*m_context);
    m_capabilities = queryCapabilities(*m_context);
    leaveWideVectorState(); // loading and starting the driver may leave it in use
    if (const auto missing = missingRequirements(m_capabilities))
        throw GlUnavailableError(missing->toStdString());
}

OffscreenGlContext::~OffscreenGlContext()
{
    if (m_context) {
        if (m_debugLog) {
            makeCurrent(); // the logger goes while its context is current
            m_debugLog.reset();
        }
        m_context->doneCurrent();
    }
}

void OffscreenGlContext::makeCurrent()
{
    m_context->makeCurrent(m_surface.get());
    leaveWideVectorState();
}

} // namespace trimlab::render
