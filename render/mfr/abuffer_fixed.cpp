#include "mfr/abuffer_fixed.h"

#include "frame_counters.h"
#include "gl/shader_library.h"
#include "gpu_scene.h"
#include "mfr/bindings.h"
#include "mfr/trim_frame.h"
#include "passes/trim_pass_state.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

constexpr std::size_t kBytesPerSlot = 8; // RG32UI, fragment_pack.glsl

} // namespace

ABufferFixed::ABufferFixed(GlFunctions& gl) : m_gl(gl), m_state(gl) {}

std::size_t ABufferFixed::requiredBytes(int width, int height, int k)
{
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    return pixels * (kBytesPerSlot * std::size_t(k) + 16);
}

std::optional<std::size_t> ABufferFixed::estimateBytes(int width, int height, const MethodParameters& parameters) const
{
    return requiredBytes(width, height, parameters.k);
}

void ABufferFixed::allocate(int width, int height, int k)
{
    if (k < 1 || k > MethodParameters::kMaxK)
        throw std::invalid_argument("k must be between 1 and " + std::to_string(MethodParameters::kMaxK) + " (got " +
                                    std::to_string(k) + ").");
    m_state.allocate(width, height);
    if (width == m_width && height == m_height && k == m_k)
        return;
    m_width = m_height = m_k = 0;
    m_fragments = GlTexture(m_gl);
    m_gl.glBindTexture(GL_TEXTURE_2D_ARRAY, m_fragments.id());
    m_gl.glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RG32UI, width, height, k);
    checkAllocation(m_gl,
                    ("AB_FP arrays (k = " + std::to_string(k) + " at " + std::to_string(width) + "x" +
                     std::to_string(height) + ")")
                        .c_str(),
                    double(requiredBytes(width, height, k)));
    m_width = width;
    m_height = height;
    m_k = k;
}

void ABufferFixed::render(TrimFrame& frame)
{
    allocate(frame.width, frame.height, frame.parameters.k);
    m_state.clear(frame.shaders);
    storePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(frame);
    m_stats = {1, 2, m_state.memoryBytes() + std::size_t(m_width) * m_height * kBytesPerSlot * std::size_t(m_k),
               false};
}

void ABufferFixed::storePass(TrimFrame& frame)
{
    const GLuint program = frame.shaders.program(QStringLiteral("abuffer_fixed_store"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_k"), m_k);
    m_state.bind();
    m_gl.glBindImageTexture(binding::kFragmentsImage, m_fragments.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RG32UI);
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void ABufferFixed::resolvePass(TrimFrame& frame)
{
    const GLuint program =
        frame.shaders.program(QStringLiteral("abuffer_fixed_resolve"), {QStringLiteral("K_MAX %1").arg(m_k)});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    m_state.bind();
    m_gl.glBindImageTexture(binding::kFragmentsImage, m_fragments.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RG32UI);
    frame.counters.bind();
    drawResolvePass(frame, program);
}

std::optional<PixelOccupancy> ABufferFixed::readOccupancy()
{
    // The counter counts every arrival, f(p); the overflow image holds the nearest lost
    // depth's code (nonzero once the pixel lost a fragment).
    PixelOccupancy occupancy = m_state.readOccupancy();
    for (std::uint32_t& held : occupancy.held)
        held = std::min(held, std::uint32_t(m_k));
    return occupancy;
}

} // namespace trimlab::render
