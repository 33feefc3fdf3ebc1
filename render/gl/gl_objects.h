#pragma once
/// \file
/// Move-only owners of OpenGL object names (buffers, textures, vertex arrays,
/// framebuffers, queries). The context that created them must be current when they die.

#include "render/gl/gl_functions.h"

#include <utility>

namespace trimlab::render {

template <void (QOpenGLFunctions_4_3_Core::*Generate)(GLsizei, GLuint*),
          void (QOpenGLFunctions_4_3_Core::*Delete)(GLsizei, const GLuint*)>
class GlName {
public:
    GlName() = default;
    explicit GlName(GlFunctions& gl) : m_gl(&gl) { (gl.*Generate)(1, &m_id); }
    ~GlName() { reset(); }
    GlName(GlName&& other) noexcept : m_gl(other.m_gl), m_id(std::exchange(other.m_id, 0u)) {}
    GlName& operator=(GlName&& other) noexcept
    {
        if (this != &other) {
            reset();
            m_gl = other.m_gl;
            m_id = std::exchange(other.m_id, 0u);
        }
        return *this;
    }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;

    [[nodiscard]] GLuint id() const { return m_id; }
    [[nodiscard]] explicit operator bool() const { return m_id != 0; }
    void reset()
    {
        if (m_id != 0)
            (m_gl->*Delete)(1, &m_id);
        m_id = 0;
    }

private:
    GlFunctions* m_gl = nullptr;
    GLuint m_id = 0;
};

using GlBuffer = GlName<&GlFunctions::glGenBuffers, &GlFunctions::glDeleteBuffers>;
using GlTexture = GlName<&GlFunctions::glGenTextures, &GlFunctions::glDeleteTextures>;
using GlVertexArray = GlName<&GlFunctions::glGenVertexArrays, &GlFunctions::glDeleteVertexArrays>;
using GlFramebuffer = GlName<&GlFunctions::glGenFramebuffers, &GlFunctions::glDeleteFramebuffers>;
using GlQuery = GlName<&GlFunctions::glGenQueries, &GlFunctions::glDeleteQueries>;

/// Drains the GL error queue after an allocation; throws GlContextLostError if
/// GL_CONTEXT_LOST was among the errors (a GPU reset), else GpuMemoryError naming `what`
/// and its size in MB if GL_OUT_OF_MEMORY was.
void checkAllocation(GlFunctions& gl, const char* what, double bytes);

} // namespace trimlab::render
