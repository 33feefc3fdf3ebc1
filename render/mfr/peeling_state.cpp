#include "render/mfr/peeling_state.h"

#include "render/gl/shader_library.h"
#include "render/gl/bindings.h"

namespace trimlab::render {

namespace {

// Mirrors of PEEL_LAYERS_F2B / PEEL_LAYERS_DUAL in shaders/common/peel_state.glsl.
constexpr int kCursorLayersF2B = 7;
constexpr int kCursorLayersDual = 14;
constexpr std::size_t kPixelStateBytes = 16; // PixelState: four R32 images
constexpr std::size_t kCursorFieldBytes = 4; // R32UI
constexpr std::size_t kWalkBytes = 16;       // RGBA32UI

int cursorLayers(bool dual)
{
    return dual ? kCursorLayersDual : kCursorLayersF2B;
}
int walkLayers(bool dual)
{
    return dual ? 2 : 1;
}

void allocateArray(GlFunctions& gl, GlTexture& texture, GLenum format, int width, int height, int layers)
{
    texture = GlTexture(gl);
    gl.glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
    gl.glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, format, width, height, layers);
}

} // namespace

PeelingState::PeelingState(GlFunctions& gl, bool dual) : m_gl(gl), m_dual(dual), m_pixels(gl)
{
}

std::size_t PeelingState::bytesPerPixel(bool dual)
{
    return kPixelStateBytes + kCursorFieldBytes * std::size_t(cursorLayers(dual)) +
           kWalkBytes * std::size_t(walkLayers(dual));
}

std::size_t PeelingState::memoryBytes() const
{
    return std::size_t(m_width) * std::size_t(m_height) * bytesPerPixel(m_dual);
}

void PeelingState::allocate(int width, int height)
{
    m_pixels.allocate(width, height);
    if (width == m_width && height == m_height)
        return;
    m_width = m_height = 0;
    allocateArray(m_gl, m_cursor, GL_R32UI, width, height, cursorLayers(m_dual));
    allocateArray(m_gl, m_walks, GL_RGBA32UI, width, height, walkLayers(m_dual));
    checkAllocation(m_gl, m_dual ? "dual depth peeling state" : "depth peeling state",
                    double(width) * height * double(bytesPerPixel(m_dual) - kPixelStateBytes));
    m_width = width;
    m_height = height;
}

void PeelingState::clear(ShaderLibrary& shaders)
{
    m_pixels.clear(shaders);
    const GLuint program = shaders.program(QStringLiteral("peeling_clear"));
    m_gl.glUseProgram(program);
    m_gl.glUniform2i(m_gl.glGetUniformLocation(program, "u_size"), m_width, m_height);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_peelLayers"), cursorLayers(m_dual));
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_walkLayers"), walkLayers(m_dual));
    bind();
    m_gl.glDispatchCompute(GLuint((m_width + 15) / 16), GLuint((m_height + 15) / 16), 1);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void PeelingState::bind()
{
    m_pixels.bind();
    m_gl.glBindImageTexture(binding::kPeelDepthImage, m_cursor.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    m_gl.glBindImageTexture(binding::kWalkImage, m_walks.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32UI);
}

} // namespace trimlab::render
