#include "render/gl/gl_functions.h"

#include "render/gl/gl_error.h"

#include <QOpenGLContext>

#include <memory>
#include <mutex>
#include <unordered_map>

namespace trimlab::render {

void GlFunctions::glFinish()
{
    ++m_gpuWaits;
    QOpenGLFunctions_4_3_Core::glFinish();
}

GLenum GlFunctions::glClientWaitSync(GLsync sync, GLbitfield flags, GLuint64 timeout)
{
    if (timeout > 0)
        ++m_gpuWaits;
    return QOpenGLFunctions_4_3_Core::glClientWaitSync(sync, flags, timeout);
}

void GlFunctions::glGetQueryObjectuiv(GLuint id, GLenum pname, GLuint* params)
{
    countQueryWait(pname);
    QOpenGLFunctions_4_3_Core::glGetQueryObjectuiv(id, pname, params);
}

void GlFunctions::glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params)
{
    countQueryWait(pname);
    QOpenGLFunctions_4_3_Core::glGetQueryObjectiv(id, pname, params);
}

void GlFunctions::glGetQueryObjectui64v(GLuint id, GLenum pname, GLuint64* params)
{
    countQueryWait(pname);
    QOpenGLFunctions_4_3_Core::glGetQueryObjectui64v(id, pname, params);
}

void GlFunctions::glGetQueryObjecti64v(GLuint id, GLenum pname, GLint64* params)
{
    countQueryWait(pname);
    QOpenGLFunctions_4_3_Core::glGetQueryObjecti64v(id, pname, params);
}

void GlFunctions::glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, GLvoid* data)
{
    ++m_gpuWaits;
    QOpenGLFunctions_4_3_Core::glGetBufferSubData(target, offset, size, data);
}

void GlFunctions::glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels)
{
    ++m_gpuWaits;
    QOpenGLFunctions_4_3_Core::glGetTexImage(target, level, format, type, pixels);
}

void GlFunctions::glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type,
                               GLvoid* pixels)
{
    ++m_gpuWaits;
    QOpenGLFunctions_4_3_Core::glReadPixels(x, y, width, height, format, type, pixels);
}

GLvoid* GlFunctions::glMapBuffer(GLenum target, GLenum access)
{
    ++m_gpuWaits;
    return QOpenGLFunctions_4_3_Core::glMapBuffer(target, access);
}

GLvoid* GlFunctions::glMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access)
{
    if ((access & GL_MAP_UNSYNCHRONIZED_BIT) == 0)
        ++m_gpuWaits;
    return QOpenGLFunctions_4_3_Core::glMapBufferRange(target, offset, length, access);
}

bool GlFunctions::tryQueryResult(GLuint query, GLuint64& result)
{
    GLuint available = GL_FALSE;
    QOpenGLFunctions_4_3_Core::glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
    if (available == GL_FALSE)
        return false;
    QOpenGLFunctions_4_3_Core::glGetQueryObjectui64v(query, GL_QUERY_RESULT, &result);
    return true;
}

bool GlFunctions::fencePassed(GLsync fence)
{
    const GLenum status = QOpenGLFunctions_4_3_Core::glClientWaitSync(fence, 0, 0);
    return status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED;
}

bool GlFunctions::tryReadBuffer(GLsync fence, GLenum target, GLintptr offset, GLsizeiptr size, GLvoid* data)
{
    if (!fencePassed(fence))
        return false;
    QOpenGLFunctions_4_3_Core::glGetBufferSubData(target, offset, size, data);
    return true;
}

namespace {

// One GlFunctions per context, dropped just before the context goes (while its function
// pointers still answer).
struct ContextFunctions {
    std::mutex mutex;
    std::unordered_map<const QOpenGLContext*, std::unique_ptr<GlFunctions>> byContext;
};

// Never destroyed: a context that outlives static destruction still finds it.
ContextFunctions& contextFunctions()
{
    static auto* functions = new ContextFunctions;
    return *functions;
}

} // namespace

GlFunctions& currentGlFunctions()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (!context)
        throw GlUnavailableError("No OpenGL context is current (programming error in the caller).");
    ContextFunctions& all = contextFunctions();
    const std::lock_guard lock(all.mutex);
    std::unique_ptr<GlFunctions>& functions = all.byContext[context];
    if (!functions) {
        auto made = std::make_unique<GlFunctions>();
        if (!made->initializeOpenGLFunctions()) {
            all.byContext.erase(context);
            throw GlUnavailableError(
                "The OpenGL context does not provide the OpenGL 4.3 core functions TrimLab needs.");
        }
        functions = std::move(made);
        QObject::connect(
            context, &QOpenGLContext::aboutToBeDestroyed, context,
            [context] {
                ContextFunctions& owner = contextFunctions();
                const std::lock_guard dropLock(owner.mutex);
                owner.byContext.erase(context);
            },
            Qt::SingleShotConnection);
    }
    return *functions;
}

} // namespace trimlab::render
