#include "render/frame/render_target.h"

#include "render/gl/gl_error.h"

#include <bit>
#include <cstring>
#include <vector>

namespace trimlab::render {

namespace {

// Bit layout of the id texel's y component (shaders/common/trim_output.glsl).
constexpr std::uint32_t kObjectMask = 0xFFu;
constexpr std::uint32_t kFrontFacingBit = 1u << 8;
constexpr std::uint32_t kBackFacingBit = 1u << 9;
constexpr std::uint32_t kOverflowedBit = 1u << 10;
constexpr std::uint32_t kUnresolvedBit = 1u << 11;
constexpr std::uint32_t kCollisionBit = 1u << 12;
constexpr int kCapShift = 13;      // 3 bits: cap plane + 1
constexpr int kCoplanarShift = 16; // 8 bits

void allocateTexture(GlFunctions& gl, GLuint texture, GLenum internalFormat, int width, int height)
{
    gl.glBindTexture(GL_TEXTURE_2D, texture);
    gl.glTexStorage2D(GL_TEXTURE_2D, 1, internalFormat, width, height);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

TrimPixel decodeInfo(const std::uint32_t* texel)
{
    TrimPixel p;
    p.windingAtStart = std::bit_cast<std::int32_t>(texel[3]);
    p.overflowed = (texel[1] & kOverflowedBit) != 0;
    p.unresolved = (texel[1] & kUnresolvedBit) != 0;
    p.capPlane = static_cast<std::int8_t>(int((texel[1] >> kCapShift) & 7u) - 1);
    if (p.capPlane >= 0)
        p.viewDepth = std::bit_cast<float>(texel[2]);
    if (texel[0] == 0)
        return p;
    p.collision = (texel[1] & kCollisionBit) != 0;
    p.coplanarCount = static_cast<std::uint8_t>((texel[1] >> kCoplanarShift) & 0xFFu);
    p.primitiveId = std::int32_t(texel[0] - 1);
    p.objectId = std::int32_t(texel[1] & kObjectMask);
    p.facing = (texel[1] & kFrontFacingBit) ? 1 : ((texel[1] & kBackFacingBit) ? -1 : 0);
    p.viewDepth = std::bit_cast<float>(texel[2]);
    return p;
}

} // namespace

RenderTarget::RenderTarget(GlFunctions& gl) : m_gl(gl), m_framebuffer(gl), m_emptyVao(gl)
{
}

void RenderTarget::drawFullscreenTriangle()
{
    m_gl.glBindVertexArray(m_emptyVao.id());
    m_gl.glDrawArrays(GL_TRIANGLES, 0, 3);
    m_gl.glBindVertexArray(0);
}

std::size_t RenderTarget::memoryBytes() const
{
    return std::size_t(m_width) * std::size_t(m_height) * (4 + 16 + 4);
}

void RenderTarget::resize(int width, int height)
{
    if (width == m_width && height == m_height)
        return;
    // Immutable storage: size changes need new textures.
    m_color = GlTexture(m_gl);
    m_info = GlTexture(m_gl);
    m_depth = GlTexture(m_gl);
    allocateTexture(m_gl, m_color.id(), GL_RGBA8, width, height);
    allocateTexture(m_gl, m_info.id(), GL_RGBA32UI, width, height);
    allocateTexture(m_gl, m_depth.id(), GL_DEPTH_COMPONENT24, width, height);
    checkAllocation(m_gl, "render target", double(width) * height * 24.0);
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_color.id(), 0);
    m_gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, m_info.id(), 0);
    m_gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.id(), 0);
    const GLenum status = m_gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("The render target framebuffer is incomplete (status 0x" +
                      QString::number(status, 16).toStdString() + ") at " + std::to_string(width) + "x" +
                      std::to_string(height) + ".");
    m_width = width;
    m_height = height;
}

void RenderTarget::bindForDrawing()
{
    static const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glDrawBuffers(2, buffers);
    m_gl.glViewport(0, 0, m_width, m_height);
}

void RenderTarget::blitColorTo(GLuint framebuffer)
{
    m_gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    m_gl.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    m_gl.glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

QImage RenderTarget::readColor()
{
    QImage image(m_width, m_height, QImage::Format_RGBA8888);
    m_gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
    m_gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    m_gl.glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.bits());
    return image.mirrored(false, true); // GL rows start at the bottom
}

TrimImage RenderTarget::readTrimImage()
{
    std::vector<std::uint32_t> texels(std::size_t(m_width) * m_height * 4);
    m_gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glReadBuffer(GL_COLOR_ATTACHMENT1);
    m_gl.glReadPixels(0, 0, m_width, m_height, GL_RGBA_INTEGER, GL_UNSIGNED_INT, texels.data());
    TrimImage image(m_width, m_height);
    for (int y = 0; y < m_height; ++y) {
        const int glRow = m_height - 1 - y;
        for (int x = 0; x < m_width; ++x)
            image.at(x, y) = decodeInfo(&texels[(std::size_t(glRow) * m_width + x) * 4]);
    }
    return image;
}

} // namespace trimlab::render
