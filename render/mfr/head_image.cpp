#include "render/mfr/head_image.h"

#include "render/gl/shader_library.h"
#include "render/gl/bindings.h"

namespace trimlab::render {

HeadImage::HeadImage(GlFunctions& gl) : m_gl(gl)
{
}

void HeadImage::allocate(int width, int height)
{
    if (width == m_width && height == m_height)
        return;
    m_width = m_height = 0;
    m_texture = GlTexture(m_gl);
    m_gl.glBindTexture(GL_TEXTURE_2D, m_texture.id());
    m_gl.glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, width, height);
    checkAllocation(m_gl, "per-pixel head image", double(width) * height * 4);
    m_width = width;
    m_height = height;
}

void HeadImage::clear(ShaderLibrary& shaders)
{
    const GLuint program = shaders.program(QStringLiteral("head_clear"));
    m_gl.glUseProgram(program);
    m_gl.glUniform2i(m_gl.glGetUniformLocation(program, "u_size"), m_width, m_height);
    bind();
    m_gl.glDispatchCompute(GLuint((m_width + 15) / 16), GLuint((m_height + 15) / 16), 1);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void HeadImage::bind()
{
    m_gl.glBindImageTexture(binding::kHeadImage, m_texture.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

} // namespace trimlab::render
