#include "render/mfr/s_buffer.h"

#include "render/frame/frame_counters.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/gl/bindings.h"
#include "render/mfr/resolve_budget.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

#include <limits>

namespace trimlab::render {

SBuffer::SBuffer(GlFunctions& gl)
    : m_gl(gl), m_state(gl), m_head(gl), m_referencing(gl), m_nodes(gl, 8, "S-buffer node buffer")
{
}

std::optional<std::size_t> SBuffer::estimateBytes(int, int, const MethodParameters&) const
{
    return std::nullopt;
}

void SBuffer::render(TrimFrame& frame)
{
    m_state.allocate(frame.width, frame.height);
    m_head.allocate(frame.width, frame.height);
    clearCountingState(frame, m_state);
    m_referencing.countPass(frame, m_state);
    m_countedTotal = m_referencing.reference(frame, m_state, m_head, frame.parameters.sharedCounters,
                                             std::numeric_limits<std::uint32_t>::max());
    m_nodes.reserve(m_countedTotal, frame.capabilities, frame.width, frame.height, frame.parameters.memoryBudgetBytes);
    storePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                         GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(frame);
    // Per-pixel passes: clear, two referencing passes (addresses, regions), resolve.
    m_stats = {2, 4, m_state.memoryBytes() + m_head.memoryBytes() + m_referencing.memoryBytes() + m_nodes.bytes(),
               false};
}

void SBuffer::storePass(TrimFrame& frame)
{
    const GLuint program = trimProgram(frame, QStringLiteral("sbuffer_store"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_nodeCapacity"), GLuint(m_countedTotal));
    m_state.bind();
    m_head.bind();
    m_nodes.bind(binding::kNodesStorage, m_countedTotal);
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void SBuffer::resolvePass(TrimFrame& frame)
{
    const GLuint program =
        trimProgram(frame, QStringLiteral("sbuffer_resolve"), {QStringLiteral("LIST_MAX %1").arg(kRegisterList)});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    setResolveLoopBudget(m_gl, program, frame.capabilities);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_nodeCapacity"), GLuint(m_countedTotal));
    m_state.bind();
    m_head.bind();
    m_nodes.bind(binding::kNodesStorage, m_countedTotal);
    frame.counters.bind();
    drawResolvePass(frame, program);
}

} // namespace trimlab::render
