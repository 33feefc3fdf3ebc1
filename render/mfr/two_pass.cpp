#include "render/mfr/two_pass.h"

#include "render/frame/frame_counters.h"
#include "render/gl/gl_error.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

#include <cmath>
#include <string>

namespace trimlab::render {

namespace {

constexpr std::size_t kPixelStateBytes = 16;
constexpr std::size_t kOwnBytesPerPixel = 8 + 4; // RG32UI fragment + 32-bit float depth
constexpr int kClosestTextureUnit = 0;

void allocateTexture(GlFunctions& gl, GlTexture& texture, GLenum format, int width, int height)
{
    texture = GlTexture(gl);
    gl.glBindTexture(GL_TEXTURE_2D, texture.id());
    gl.glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST); // integer: no filtering
    gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

// A power of two with zFar * scale < 1/2: multiplying a view depth by it is exact in
// float, so the depth buffer orders and ties fragments exactly as their view depths.
float depthScale(double zFar)
{
    int exponent = 0;
    std::frexp(zFar, &exponent); // zFar < 2^exponent
    return float(std::ldexp(1.0, -(exponent + 1)));
}

} // namespace

TwoPassTrim::TwoPassTrim(GlFunctions& gl) : m_gl(gl), m_state(gl)
{
}

std::size_t TwoPassTrim::requiredBytes(int width, int height)
{
    return std::size_t(width) * std::size_t(height) * (kPixelStateBytes + kOwnBytesPerPixel);
}

std::optional<std::size_t> TwoPassTrim::estimateBytes(int width, int height, const MethodParameters&) const
{
    return requiredBytes(width, height);
}

void TwoPassTrim::allocate(int width, int height)
{
    m_state.allocate(width, height);
    if (width == m_width && height == m_height)
        return;
    m_width = m_height = 0;
    allocateTexture(m_gl, m_closest, GL_RG32UI, width, height);
    allocateTexture(m_gl, m_depth, GL_DEPTH_COMPONENT32F, width, height);
    checkAllocation(m_gl, "two-pass closest fragment", double(width) * height * double(kOwnBytesPerPixel));
    m_framebuffer = GlFramebuffer(m_gl);
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_closest.id(), 0);
    m_gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m_depth.id(), 0);
    const GLenum status = m_gl.glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("The two-pass framebuffer is incomplete (status 0x" + QString::number(status, 16).toStdString() +
                      ") at " + std::to_string(width) + "x" + std::to_string(height) + ".");
    m_width = width;
    m_height = height;
}

void TwoPassTrim::render(TrimFrame& frame)
{
    allocate(frame.width, frame.height);
    clearCountingState(frame, m_state);
    countPass(frame);
    closestPass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    resolvePass(frame);
    m_stats = {2, 2, m_state.memoryBytes() + std::size_t(m_width) * m_height * kOwnBytesPerPixel, false};
}

void TwoPassTrim::countPass(TrimFrame& frame)
{
    const GLuint program = trimProgram(frame, QStringLiteral("two_pass_count"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_state.bind();
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void TwoPassTrim::closestPass(TrimFrame& frame)
{
    const GLuint program = trimProgram(frame, QStringLiteral("two_pass_closest"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1f(m_gl.glGetUniformLocation(program, "u_depthScale"), depthScale(frame.camera.zFar));
    m_gl.glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    m_gl.glViewport(0, 0, m_width, m_height);
    const GLuint noFragment[4] = {0, 0, 0, 0};
    const GLfloat farthest = 1.0f;
    m_gl.glClearBufferuiv(GL_COLOR, 0, noFragment);
    m_gl.glClearBufferfv(GL_DEPTH, 0, &farthest);
    m_gl.glEnable(GL_DEPTH_TEST);
    m_gl.glDepthFunc(GL_LESS);
    m_gl.glDepthMask(GL_TRUE);
    m_gl.glDisable(GL_CULL_FACE);
    m_gl.glDisable(GL_BLEND);
    frame.scene.draw(program, frame.projection);
    m_gl.glDisable(GL_DEPTH_TEST);
}

void TwoPassTrim::resolvePass(TrimFrame& frame)
{
    const GLuint program = trimProgram(frame, QStringLiteral("two_pass_resolve"));
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    m_gl.glActiveTexture(GL_TEXTURE0 + kClosestTextureUnit);
    m_gl.glBindTexture(GL_TEXTURE_2D, m_closest.id());
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_closest"), kClosestTextureUnit);
    m_state.bind();
    frame.counters.bind();
    drawResolvePass(frame, program);
}

} // namespace trimlab::render
