#include "mfr/kplus_buffer.h"

#include "gl/gl_error.h"
#include "gl/shader_library.h"

#include <string>

namespace trimlab::render {

namespace {

constexpr std::size_t kBytesPerFragment = 8; // RG32UI, fragment_pack.glsl
constexpr std::size_t kBytesPerPixelState = 4 * 4; // counter, semaphore, winding, overflow

// A single-channel 32-bit image read back with row 0 at the top.
std::vector<std::uint32_t> readImageTopDown(GlFunctions& gl, GLuint texture, GLenum format, int width, int height)
{
    std::vector<std::uint32_t> bottomUp(std::size_t(width) * height);
    gl.glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    gl.glBindTexture(GL_TEXTURE_2D, texture);
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.glGetTexImage(GL_TEXTURE_2D, 0, format, GL_UNSIGNED_INT, bottomUp.data());
    std::vector<std::uint32_t> topDown(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(&bottomUp[std::size_t(height - 1 - y) * width], width, &topDown[std::size_t(y) * width]);
    return topDown;
}

void allocateImage(GlFunctions& gl, GLuint texture, GLenum format, int width, int height)
{
    gl.glBindTexture(GL_TEXTURE_2D, texture);
    gl.glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
}

} // namespace

KPlusBuffer::KPlusBuffer(GlFunctions& gl, ShaderLibrary& shaders) : m_gl(gl), m_shaders(shaders) {}

std::size_t KPlusBuffer::requiredBytes(int width, int height, int k)
{
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    return pixels * (kBytesPerFragment * std::size_t(k) + kBytesPerPixelState);
}

std::size_t KPlusBuffer::memoryBytes() const
{
    return requiredBytes(m_width, m_height, m_k);
}

void KPlusBuffer::allocate(int width, int height, int k)
{
    if (k < 1 || k > kMaxK)
        throw std::invalid_argument("k must be between 1 and " + std::to_string(kMaxK) + " (got " + std::to_string(k) + ").");
    if (width == m_width && height == m_height && k == m_k)
        return;
    m_counter = GlTexture(m_gl);
    m_semaphore = GlTexture(m_gl);
    m_winding = GlTexture(m_gl);
    m_overflow = GlTexture(m_gl);
    m_fragments = GlTexture(m_gl);
    m_width = m_height = m_k = 0;
    allocateImage(m_gl, m_counter.id(), GL_R32UI, width, height);
    allocateImage(m_gl, m_semaphore.id(), GL_R32UI, width, height);
    allocateImage(m_gl, m_winding.id(), GL_R32I, width, height);
    allocateImage(m_gl, m_overflow.id(), GL_R32UI, width, height);
    // The thesis's "3D array buffer": one RG32UI layer per fragment slot. A layered texture
    // is not bound by the driver's shader-storage block limit (128 MB on llvmpipe).
    m_gl.glBindTexture(GL_TEXTURE_2D_ARRAY, m_fragments.id());
    m_gl.glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RG32UI, width, height, k);
    checkAllocation(m_gl, ("k+-buffer (k = " + std::to_string(k) + " at " + std::to_string(width) + "x" +
                           std::to_string(height) + ")").c_str(),
                    double(requiredBytes(width, height, k)));
    m_width = width;
    m_height = height;
    m_k = k;
}

void KPlusBuffer::clear()
{
    const GLuint program = m_shaders.program(QStringLiteral("kplus_clear"));
    m_gl.glUseProgram(program);
    m_gl.glUniform2i(m_gl.glGetUniformLocation(program, "u_size"), m_width, m_height);
    m_gl.glBindImageTexture(0, m_counter.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    m_gl.glBindImageTexture(1, m_semaphore.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    m_gl.glBindImageTexture(2, m_winding.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32I);
    m_gl.glBindImageTexture(3, m_overflow.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    m_gl.glDispatchCompute(GLuint((m_width + 15) / 16), GLuint((m_height + 15) / 16), 1);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void KPlusBuffer::bindImages()
{
    m_gl.glBindImageTexture(0, m_counter.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    m_gl.glBindImageTexture(1, m_semaphore.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    m_gl.glBindImageTexture(2, m_winding.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32I);
    m_gl.glBindImageTexture(3, m_overflow.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    m_gl.glBindImageTexture(4, m_fragments.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RG32UI);
}

KPlusOccupancy KPlusBuffer::readOccupancy()
{
    KPlusOccupancy occupancy{m_width, m_height, {}, {}};
    occupancy.held = readImageTopDown(m_gl, m_counter.id(), GL_RED_INTEGER, m_width, m_height);
    const std::vector<std::uint32_t> flags = readImageTopDown(m_gl, m_overflow.id(), GL_RED_INTEGER, m_width, m_height);
    occupancy.overflowed.assign(flags.begin(), flags.end());
    return occupancy;
}

} // namespace trimlab::render
