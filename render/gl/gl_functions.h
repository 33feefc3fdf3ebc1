#pragma once
/// \file
/// The OpenGL entry points the render layer uses: the 4.3 core function table of the
/// current context (Qt resolves it; no loader library needed), with the calls that make
/// the CPU wait for the GPU counted.
///
/// A frame that reads a result of its own GPU work before the GPU has finished it stalls
/// the CPU until then: CPU and GPU work in series instead of overlapping. The calls below
/// hide the base class's ones of the same name (every caller goes through GlFunctions)
/// and count each call that may wait that way, so that a test can prove a frame path
/// free of them. What counts: glFinish; glClientWaitSync with a timeout; a query's
/// GL_QUERY_RESULT; reading a buffer or image into client memory (glGetBufferSubData,
/// glGetTexImage, glReadPixels — TrimLab never reads into a pixel-pack buffer); mapping a
/// buffer without GL_MAP_UNSYNCHRONIZED_BIT. The try* calls read results the GPU has
/// already delivered and never wait.

#include <QOpenGLFunctions_4_3_Core>

#include <cstdint>

namespace trimlab::render {

class GlFunctions : public QOpenGLFunctions_4_3_Core {
public:
    /// Calls so far that may have made the CPU wait for the GPU (see the file comment).
    [[nodiscard]] std::uint64_t gpuWaits() const { return m_gpuWaits; }

    void glFinish();
    GLenum glClientWaitSync(GLsync sync, GLbitfield flags, GLuint64 timeout);
    void glGetQueryObjectuiv(GLuint id, GLenum pname, GLuint* params);
    void glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params);
    void glGetQueryObjectui64v(GLuint id, GLenum pname, GLuint64* params);
    void glGetQueryObjecti64v(GLuint id, GLenum pname, GLint64* params);
    void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, GLvoid* data);
    void glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels);
    void glReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, GLvoid* pixels);
    GLvoid* glMapBuffer(GLenum target, GLenum access);
    GLvoid* glMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access);

    /// The 64-bit result of `query` if the GPU has delivered it; false (nothing read)
    /// while it is still pending.
    [[nodiscard]] bool tryQueryResult(GLuint query, GLuint64& result);
    /// Whether the GPU has passed `fence` (a glFenceSync); never waits.
    [[nodiscard]] bool fencePassed(GLsync fence);
    /// Copies `size` bytes at `offset` of the buffer bound to `target` into `data` if the
    /// GPU has passed `fence`, which must follow the last GPU write of that range; false
    /// (nothing read) while it has not.
    [[nodiscard]] bool tryReadBuffer(GLsync fence, GLenum target, GLintptr offset, GLsizeiptr size, GLvoid* data);

private:
    /// GL_QUERY_RESULT waits until the GPU has answered (GL_QUERY_RESULT_AVAILABLE does not).
    void countQueryWait(GLenum pname) { m_gpuWaits += pname == GL_QUERY_RESULT ? 1 : 0; }

    std::uint64_t m_gpuWaits = 0;
};

/// The functions of the current context, made on first use and kept until the context is
/// destroyed. Throws GlUnavailableError when there is no current context or it cannot
/// provide OpenGL 4.3 core.
[[nodiscard]] GlFunctions& currentGlFunctions();

} // namespace trimlab::render
