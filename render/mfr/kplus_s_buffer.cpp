#include "render/mfr/kplus_s_buffer.h"

#include "render/frame/frame_counters.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/gl/bindings.h"
#include "render/mfr/kplus_buffer.h"
#include "render/mfr/method_parameter_table.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

// Bounded spin of the store pass's lock, as for the k⁺-buffer (kplus_buffer.cpp).
constexpr int kMaxSpin = 4096;

} // namespace

KPlusSBuffer::KPlusSBuffer(GlFunctions& gl)
    : m_gl(gl), m_state(gl), m_head(gl), m_referencing(gl), m_nodes(gl, 8, "K+B-SB node buffer")
{
}

std::optional<std::size_t> KPlusSBuffer::estimateBytes(int, int, const MethodParameters&) const
{
    return std::nullopt;
}

void KPlusSBuffer::render(TrimFrame& frame)
{
    m_k = frame.parameters.k;
    requireParameterValue(method_parameters::kK, m_k);
    const KPlusLock lock = chooseKPlusLock(frame.capabilities, frame.parameters.allowInterlock);
    m_state.allocate(frame.width, frame.height);
    m_head.allocate(frame.width, frame.height);
    clearCountingState(frame, m_state);
    m_referencing.countPass(frame, m_state);
    m_countedTotal =
        m_referencing.reference(frame, m_state, m_head, frame.parameters.sharedCounters, std::uint32_t(m_k));
    m_nodes.reserve(m_countedTotal, frame.capabilities, frame.width, frame.height, frame.parameters.memoryBudgetBytes);
    storePass(frame, lock);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                         GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(frame);
    // Per-pixel passes: clear, two referencing passes (addresses, regions), resolve.
    m_stats = {.geometryPasses = 2,
               .fullscreenPasses = 4,
               .bytes = m_state.memoryBytes() + m_head.memoryBytes() + m_referencing.memoryBytes() + m_nodes.bytes(),
               .interlock = lock != KPlusLock::SpinLock,
               .usesLock = true};
}

void KPlusSBuffer::storePass(TrimFrame& frame, KPlusLock lock)
{
    QStringList defines = kplusStoreDefines(lock, false);
    defines << QStringLiteral("KPLUS_NODE_REGION");
    const GLuint program = trimProgram(frame, QStringLiteral("kplus_sbuffer_store"), defines);
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_k"), m_k);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_maxSpin"), kMaxSpin);
    m_state.bind();
    m_head.bind();
    m_nodes.bind(binding::kNodesStorage, m_countedTotal);
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void KPlusSBuffer::resolvePass(TrimFrame& frame)
{
    const GLuint program = trimProgram(frame, QStringLiteral("kplus_sbuffer_resolve"),
                                       {QStringLiteral("KPLUS_NODE_REGION"), QStringLiteral("K_MAX %1").arg(m_k)});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    m_state.bind();
    m_head.bind();
    m_nodes.bind(binding::kNodesStorage, m_countedTotal);
    frame.counters.bind();
    drawResolvePass(frame, program);
}

} // namespace trimlab::render
