#pragma once
/// \file
/// An OpenGL 4.3 core context without a window, for the `render`/`bench` verbs and tests.
/// Needs a QGuiApplication; on this platform also an X display (Xvfb), see docs/llvmpipe-notes.md.

#include "render/gl/gl_capabilities.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>

#include <memory>

class QOpenGLDebugLogger;

namespace trimlab::render {

class OffscreenGlContext {
public:
    /// Creates the context and makes it current. Throws GlUnavailableError with a clear
    /// message when no 4.3 core context can be created.
    OffscreenGlContext();
    ~OffscreenGlContext();
    OffscreenGlContext(const OffscreenGlContext&) = delete;
    OffscreenGlContext& operator=(const OffscreenGlContext&) = delete;

    void makeCurrent();
    [[nodiscard]] QOpenGLContext& context() { return *m_context; }
    [[nodiscard]] const GlCapabilities& capabilities() const { return m_capabilities; }

    /// The surface format TrimLab asks for everywhere (4.3 core, 24-bit depth).
    [[nodiscard]] static QSurfaceFormat requestedFormat();

private:
    std::unique_ptr<QOffscreenSurface> m_surface;
    std::unique_ptr<QOpenGLContext> m_context;
    GlCapabilities m_capabilities;
    std::unique_ptr<QOpenGLDebugLogger> m_debugLog; ///< with TRIMLAB_GL_DEBUG only (gl_debug_log.h)
};

} // namespace trimlab::render
