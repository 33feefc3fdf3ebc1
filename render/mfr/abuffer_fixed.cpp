#include "render/mfr/abuffer_fixed.h"

#include "render/frame/frame_counters.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

#include <algorithm>

namespace trimlab::render {

namespace {

} // namespace

ABufferFixed::ABufferFixed(GlFunctions& gl) : m_gl(gl), m_state(gl), m_slots(gl)
{
}

std::optional<std::size_t> ABufferFixed::estimateBytes(int width, int height, const MethodParameters& parameters) const
{
    return SlotArray::slotBytes(width, height, parameters.k) + PixelState::bytesFor(width, height);
}

void ABufferFixed::render(TrimFrame& frame)
{
    m_slots.allocate(frame.width, frame.height, frame.parameters.k, "AB_FP arrays");
    m_state.allocate(frame.width, frame.height);
    clearCountingState(frame, m_state);
    storePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(frame);
    m_stats = {.geometryPasses = 1, .fullscreenPasses = 2, .bytes = m_state.memoryBytes() + m_slots.bytes()};
}

void ABufferFixed::storePass(TrimFrame& frame)
{
    const GLuint program = trimProgram(frame, QStringLiteral("abuffer_fixed_store"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_k"), m_slots.k());
    m_state.bind();
    m_slots.bind();
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void ABufferFixed::resolvePass(TrimFrame& frame)
{
    const GLuint program =
        trimProgram(frame, QStringLiteral("abuffer_fixed_resolve"), {QStringLiteral("K_MAX %1").arg(m_slots.k())});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    m_state.bind();
    m_slots.bind();
    frame.counters.bind();
    drawResolvePass(frame, program);
}

std::optional<PixelOccupancy> ABufferFixed::readOccupancy()
{
    // The counter counts every arrival, f(p); the overflow image holds the nearest lost
    // depth's code (nonzero once the pixel lost a fragment).
    PixelOccupancy occupancy = m_state.readOccupancy();
    for (std::uint32_t& held : occupancy.held)
        held = std::min(held, std::uint32_t(m_slots.k()));
    return occupancy;
}

} // namespace trimlab::render
