#pragma once
/// \file
/// The driver's own account of what went wrong, on request: with TRIMLAB_GL_DEBUG set in
/// the environment, contexts are made as debug contexts and every message the driver
/// reports (KHR_debug: errors, undefined behaviour, performance warnings; not its
/// notifications) goes to the Qt log as it happens. For finding a fault that shows on one
/// vendor's driver only (the bare GPU machine, scripts/gpu-check --probe); off by default
/// because a debug context is slower and the messages are for developers.

#include <QOpenGLContext>
#include <QSurfaceFormat>

#include <memory>

class QOpenGLDebugLogger;

namespace trimlab::render {

/// True when TRIMLAB_GL_DEBUG is set (to anything but 0).
[[nodiscard]] bool glDebugRequested();

/// `format` with QSurfaceFormat::DebugContext added when glDebugRequested().
[[nodiscard]] QSurfaceFormat withDebugRequest(QSurfaceFormat format);

/// Starts logging the current context's debug messages synchronously (each message in
/// the call that caused it) when glDebugRequested() and the context has KHR_debug; null
/// otherwise. The logger must die while its context is current.
[[nodiscard]] std::unique_ptr<QOpenGLDebugLogger> startGlDebugLog(QOpenGLContext& context);

} // namespace trimlab::render
