#include "render/mfr/kplus_buffer.h"

#include "render/frame/frame_counters.h"
#include "render/gl/gl_capabilities.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

namespace trimlab::render {

namespace {

// Spin iterations before a fragment gives up the lock (counted, never silent). Far above
// what llvmpipe needs (it serialises a pixel's fragments); bounds GPU livelock.
constexpr int kMaxSpin = 4096;

} // namespace

KPlusLock chooseKPlusLock(const GlCapabilities& caps, bool allowInterlock)
{
    if (!allowInterlock)
        return KPlusLock::SpinLock;
    return caps.hasExtension("GL_ARB_fragment_shader_interlock") ? KPlusLock::InterlockArb : KPlusLock::SpinLock;
}

QStringList kplusStoreDefines(KPlusLock lock, bool heap)
{
    QStringList defines;
    if (heap)
        defines << QStringLiteral("KPLUS_HEAP");
    if (lock == KPlusLock::InterlockArb)
        defines << QStringLiteral("KPLUS_INTERLOCK_ARB");
    return defines;
}

KPlusBuffer::KPlusBuffer(GlFunctions& gl, bool heap) : m_gl(gl), m_heap(heap), m_state(gl), m_slots(gl)
{
}

FragmentMethodKind KPlusBuffer::kind() const
{
    return m_heap ? FragmentMethodKind::KPlusHeap : FragmentMethodKind::KPlusArray;
}

std::optional<std::size_t> KPlusBuffer::estimateBytes(int width, int height, const MethodParameters& parameters) const
{
    return SlotArray::slotBytes(width, height, parameters.k) + PixelState::bytesFor(width, height);
}

void KPlusBuffer::render(TrimFrame& frame)
{
    m_slots.allocate(frame.width, frame.height, frame.parameters.k, "k+-buffer");
    m_state.allocate(frame.width, frame.height);
    const KPlusLock lock = chooseKPlusLock(frame.capabilities, frame.parameters.allowInterlock);
    clearCountingState(frame, m_state);
    storePass(frame, lock);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(frame);
    m_stats = {.geometryPasses = 1,
               .fullscreenPasses = 2,
               .bytes = m_state.memoryBytes() + m_slots.bytes(),
               .interlock = lock != KPlusLock::SpinLock,
               .usesLock = true};
}

void KPlusBuffer::storePass(TrimFrame& frame, KPlusLock lock)
{
    const GLuint program = trimProgram(frame, QStringLiteral("kplus_store"), kplusStoreDefines(lock, m_heap));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_k"), m_slots.k());
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_maxSpin"), kMaxSpin);
    m_state.bind();
    m_slots.bind();
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void KPlusBuffer::resolvePass(TrimFrame& frame)
{
    const GLuint program =
        trimProgram(frame, QStringLiteral("kplus_resolve"), {QStringLiteral("K_MAX %1").arg(m_slots.k())});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    m_state.bind();
    m_slots.bind();
    frame.counters.bind();
    drawResolvePass(frame, program);
}

} // namespace trimlab::render
