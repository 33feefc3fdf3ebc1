#pragma once
/// \file
/// GPU resets: a driver's watchdog (e.g. Windows' TDR after a frame ran for seconds) or
/// a GPU fault throws away every object of the OpenGL contexts it hits. The driver says so
/// only to contexts created with reset notification (QSurfaceFormat::ResetNotification →
/// GL_LOSE_CONTEXT_ON_RESET): glGetGraphicsResetStatus then reports the reset and every
/// later GL call fails with GL_CONTEXT_LOST; on platforms where Qt honours the request it
/// also marks the QOpenGLContext invalid. Other contexts are never told — Qt 6.4 on GLX
/// (Linux) does not pass the request on, so there a reset goes unnoticed by design of the
/// platform (docs/reliability.md).
///
/// The renderer polls the status after each frame (ContextResetWatch) and turns a reset
/// into GlContextLostError; the viewport then re-creates its context and uploads the
/// scene again, the batch verbs render the frame again once.

#include "render/gl/gl_error.h"

#include <QOpenGLContext>

namespace trimlab::render {

/// What glGetGraphicsResetStatus said.
enum class ContextReset {
    None,     ///< GL_NO_ERROR: no reset since the last poll
    Guilty,   ///< GL_GUILTY_CONTEXT_RESET: this context's own work caused it
    Innocent, ///< GL_INNOCENT_CONTEXT_RESET: another context (application) caused it
    Unknown,  ///< GL_UNKNOWN_CONTEXT_RESET, GL_CONTEXT_LOST, or Qt marked the context invalid
};

/// The reset a glGetGraphicsResetStatus value names (an unknown value: Unknown, since
/// anything but GL_NO_ERROR means the objects are gone).
[[nodiscard]] ContextReset contextResetFromStatus(unsigned status);

/// What happened and what to do, for GlContextLostError and the status bar: a guilty
/// reset blames the frame's work (pick a method that holds less, lower k or the view
/// size), an innocent one another application.
[[nodiscard]] std::string contextResetMessage(ContextReset reset);

/// The GPU reset the context: its objects (scene, buffers, programs) are gone.
class GlContextLostError : public GlError {
public:
    explicit GlContextLostError(ContextReset reset) : GlError(contextResetMessage(reset)), m_reset(reset) {}
    [[nodiscard]] ContextReset reset() const { return m_reset; }

private:
    ContextReset m_reset;
};

/// GL_CONTEXT_LOST (0x0507), which glGetError reports for calls made after a reset.
inline constexpr unsigned kGlContextLost = 0x0507;

/// Polls one context's reset status. Construct it with the context current.
class ContextResetWatch {
public:
    explicit ContextResetWatch(QOpenGLContext& context);

    /// Whether the driver tells this context about resets (strategy
    /// GL_LOSE_CONTEXT_ON_RESET and glGetGraphicsResetStatus resolved). When false, poll()
    /// can still see a context Qt marked invalid.
    [[nodiscard]] bool notifies() const { return m_status != nullptr; }
    /// The context must be current. None when nothing happened.
    [[nodiscard]] ContextReset poll() const;
    /// Throws GlContextLostError when poll() reports a reset.
    void throwIfReset() const;

private:
    using StatusFunction = GLenum(QOPENGLF_APIENTRYP)();
    QOpenGLContext* m_context;
    StatusFunction m_status = nullptr;
};

} // namespace trimlab::render
