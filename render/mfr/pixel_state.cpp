#include "render/mfr/pixel_state.h"

#include "render/gl/shader_library.h"
#include "render/gl/bindings.h"

#include <algorithm>

namespace trimlab::render {

namespace {

constexpr std::size_t kBytesPerPixel = 4 * 4; // four R32 images

void allocateImage(GlFunctions& gl, GlTexture& texture, GLenum format, int width, int height)
{
    texture = GlTexture(gl);
    gl.glBindTexture(GL_TEXTURE_2D, texture.id());
    gl.glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
}

} // namespace

std::vector<std::uint32_t> readImageTopDown(GlFunctions& gl, GLuint texture, int width, int height)
{
    std::vector<std::uint32_t> bottomUp(std::size_t(width) * height);
    gl.glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    gl.glBindTexture(GL_TEXTURE_2D, texture);
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, bottomUp.data());
    std::vector<std::uint32_t> topDown(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(&bottomUp[std::size_t(height - 1 - y) * width], width, &topDown[std::size_t(y) * width]);
    return topDown;
}

PixelState::PixelState(GlFunctions& gl) : m_gl(gl)
{
}

std::size_t PixelState::bytesFor(int width, int height)
{
    return std::size_t(width) * std::size_t(height) * kBytesPerPixel;
}

void PixelState::allocate(int width, int height)
{
    if (width == m_width && height == m_height)
        return;
    m_width = m_height = 0;
    allocateImage(m_gl, m_counter, GL_R32UI, width, height);
    allocateImage(m_gl, m_semaphore, GL_R32UI, width, height);
    allocateImage(m_gl, m_winding, GL_R32I, width, height);
    allocateImage(m_gl, m_overflow, GL_R32UI, width, height);
    checkAllocation(m_gl, "per-pixel counters", double(width) * height * kBytesPerPixel);
    m_width = width;
    m_height = height;
}

void PixelState::clear(ShaderLibrary& shaders)
{
    const GLuint program = shaders.program(QStringLiteral("pixel_state_clear"));
    m_gl.glUseProgram(program);
    m_gl.glUniform2i(m_gl.glGetUniformLocation(program, "u_size"), m_width, m_height);
    bind();
    m_gl.glDispatchCompute(GLuint((m_width + 15) / 16), GLuint((m_height + 15) / 16), 1);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void PixelState::bind()
{
    m_gl.glBindImageTexture(binding::kCounterImage, m_counter.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    m_gl.glBindImageTexture(binding::kSemaphoreImage, m_semaphore.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    m_gl.glBindImageTexture(binding::kWindingImage, m_winding.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32I);
    m_gl.glBindImageTexture(binding::kOverflowImage, m_overflow.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

PixelOccupancy PixelState::readOccupancy()
{
    PixelOccupancy occupancy{m_width, m_height, {}, {}};
    occupancy.held = readImageTopDown(m_gl, m_counter.id(), m_width, m_height);
    const std::vector<std::uint32_t> flags = readImageTopDown(m_gl, m_overflow.id(), m_width, m_height);
    occupancy.overflowed.resize(flags.size());
    // Any nonzero value is an overflow (AB_FP keeps a depth code there, not just 1).
    std::transform(flags.begin(), flags.end(), occupancy.overflowed.begin(),
                   [](std::uint32_t flag) { return std::uint8_t(flag != 0 ? 1 : 0); });
    return occupancy;
}

} // namespace trimlab::render
