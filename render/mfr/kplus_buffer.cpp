#include "mfr/kplus_buffer.h"

#include "frame_counters.h"
#include "gl/gl_capabilities.h"
#include "gl/shader_library.h"
#include "gpu_scene.h"
#include "mfr/bindings.h"
#include "mfr/trim_frame.h"
#include "passes/trim_pass_state.h"

#include <stdexcept>
#include <string>

namespace trimlab::render {

namespace {

constexpr std::size_t kBytesPerSlot = 8; // RG32UI, fragment_pack.glsl
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

const char* kplusLockName(KPlusLock lock)
{
    switch (lock) {
    case KPlusLock::SpinLock:
        return "spin-lock";
    case KPlusLock::InterlockArb:
        return "GL_ARB_fragment_shader_interlock";
    }
    return "?";
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

KPlusBuffer::KPlusBuffer(GlFunctions& gl, bool heap) : m_gl(gl), m_heap(heap), m_state(gl) {}

FragmentMethodKind KPlusBuffer::kind() const
{
    return m_heap ? FragmentMethodKind::KPlusHeap : FragmentMethodKind::KPlusArray;
}

std::size_t KPlusBuffer::requiredBytes(int width, int height, int k)
{
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    return pixels * (kBytesPerSlot * std::size_t(k) + 16);
}

std::optional<std::size_t> KPlusBuffer::estimateBytes(int width, int height, const MethodParameters& parameters) const
{
    return requiredBytes(width, height, parameters.k);
}

void KPlusBuffer::allocate(int width, int height, int k)
{
    if (k < 1 || k > MethodParameters::kMaxK)
        throw std::invalid_argument("k must be between 1 and " + std::to_string(MethodParameters::kMaxK) + " (got " +
                                    std::to_string(k) + ").");
    m_state.allocate(width, height);
    if (width == m_width && height == m_height && k == m_k)
        return;
    m_width = m_height = m_k = 0;
    // The thesis's "3D array buffer": one RG32UI layer per slot. A layered texture is not
    // bound by the driver's shader-storage block limit (128 MB on llvmpipe).
    m_fragments = GlTexture(m_gl);
    m_gl.glBindTexture(GL_TEXTURE_2D_ARRAY, m_fragments.id());
    m_gl.glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RG32UI, width, height, k);
    checkAllocation(m_gl,
                    ("k+-buffer (k = " + std::to_string(k) + " at " + std::to_string(width) + "x" +
                     std::to_string(height) + ")")
                        .c_str(),
                    double(requiredBytes(width, height, k)));
    m_width = width;
    m_height = height;
    m_k = k;
}

void KPlusBuffer::bindFragments()
{
    m_gl.glBindImageTexture(binding::kFragmentsImage, m_fragments.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RG32UI);
}

void KPlusBuffer::render(TrimFrame& frame)
{
    allocate(frame.width, frame.height, frame.parameters.k);
    const KPlusLock lock = chooseKPlusLock(frame.capabilities, frame.parameters.allowInterlock);
    m_state.clear(frame.shaders);
    storePass(frame, lock);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
    resolvePass(frame);
    m_stats = {.geometryPasses = 1,
               .fullscreenPasses = 2,
               .bytes = m_state.memoryBytes() + std::size_t(m_width) * m_height * kBytesPerSlot * std::size_t(m_k),
               .interlock = lock != KPlusLock::SpinLock,
               .usesLock = true};
}

void KPlusBuffer::storePass(TrimFrame& frame, KPlusLock lock)
{
    const GLuint program = frame.shaders.program(QStringLiteral("kplus_store"), kplusStoreDefines(lock, m_heap));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_k"), m_k);
    m_gl.glUniform1i(m_gl.glGetUniformLocation(program, "u_maxSpin"), kMaxSpin);
    m_state.bind();
    bindFragments();
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
}

void KPlusBuffer::resolvePass(TrimFrame& frame)
{
    const GLuint program = frame.shaders.program(QStringLiteral("kplus_resolve"), {QStringLiteral("K_MAX %1").arg(m_k)});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    m_state.bind();
    bindFragments();
    frame.counters.bind();
    drawResolvePass(frame, program);
}

} // namespace trimlab::render
