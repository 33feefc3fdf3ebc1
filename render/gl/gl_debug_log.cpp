#include "render/gl/gl_debug_log.h"

#include <QOpenGLDebugLogger>
#include <QDebug>
#include <QtGlobal>

namespace trimlab::render {

bool glDebugRequested()
{
    const QByteArray value = qgetenv("TRIMLAB_GL_DEBUG");
    return !value.isEmpty() && value != "0";
}

QSurfaceFormat withDebugRequest(QSurfaceFormat format)
{
    if (glDebugRequested())
        format.setOption(QSurfaceFormat::DebugContext);
    return format;
}

std::unique_ptr<QOpenGLDebugLogger> startGlDebugLog(QOpenGLContext& context)
{
    if (!glDebugRequested())
        return nullptr;
    auto logger = std::make_unique<QOpenGLDebugLogger>();
    if (!logger->initialize()) {
        qWarning("TRIMLAB_GL_DEBUG: this %s context has no KHR_debug; no driver messages will be shown.",
                 context.format().testOption(QSurfaceFormat::DebugContext) ? "debug" : "non-debug");
        return nullptr;
    }
    QObject::connect(logger.get(), &QOpenGLDebugLogger::messageLogged, [](const QOpenGLDebugMessage& message) {
        qWarning() << "GL debug:" << message; // source, type, severity, id and the driver's text
    });
    // Every source, type and severity but the notifications (NVIDIA reports where each
    // buffer lives, hundreds of lines a test).
    logger->enableMessages();
    logger->disableMessages(QOpenGLDebugMessage::AnySource, QOpenGLDebugMessage::AnyType,
                            QOpenGLDebugMessage::NotificationSeverity);
    logger->startLogging(QOpenGLDebugLogger::SynchronousLogging);
    return logger;
}

} // namespace trimlab::render
