#include "render/mfr/abuffer_linked_list.h"

#include "render/frame/frame_counters.h"
#include "render/gl/gl_capabilities.h"
#include "render/gl/shader_library.h"
#include "render/frame/gpu_scene.h"
#include "render/gl/bindings.h"
#include "render/mfr/resolve_budget.h"
#include "render/mfr/trim_frame.h"
#include "render/mfr/trim_pass_state.h"

#include <algorithm>

namespace trimlab::render {

ABufferLinkedList::ABufferLinkedList(GlFunctions& gl)
    : m_gl(gl), m_state(gl), m_head(gl), m_nodes(gl, 8, "AB_LL node buffer"), m_links(gl, 4, "AB_LL link buffer")
{
}

std::optional<std::size_t> ABufferLinkedList::estimateBytes(int, int, const MethodParameters&) const
{
    return std::nullopt;
}

void ABufferLinkedList::setNodeCapacity(std::uint64_t fragments, const GlCapabilities& capabilities)
{
    m_nodes.reallocate(fragments, capabilities, 0, 0);
    m_links.reallocate(fragments, capabilities, 0, 0);
}

void ABufferLinkedList::allocate(const TrimFrame& frame)
{
    m_state.allocate(frame.width, frame.height);
    m_head.allocate(frame.width, frame.height);
    if (!m_nodeCounter) {
        m_nodeCounter = GlBuffer(m_gl);
        m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_nodeCounter.id());
        m_gl.glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
        checkAllocation(m_gl, "AB_LL node counter", sizeof(GLuint));
    }
    if (m_nodes.capacity() == 0) {
        const std::uint64_t guess =
            std::uint64_t(frame.width) * std::uint64_t(frame.height) * kInitialFragmentsPerPixel;
        // Links and nodes share the budget: half each.
        const std::size_t budget = frame.parameters.memoryBudgetBytes / 2;
        setNodeCapacity(std::min(guess, m_nodes.maxNodes(frame.capabilities, budget)), frame.capabilities);
    }
}

void ABufferLinkedList::grow(std::uint64_t needed, const TrimFrame& frame)
{
    const std::size_t budget = frame.parameters.memoryBudgetBytes / 2; // links and nodes share it
    const std::uint64_t limit = m_nodes.maxNodes(frame.capabilities, budget);
    const std::uint64_t target = needed > limit ? needed : std::min(needed + needed / 8, limit);
    m_nodes.reallocate(target, frame.capabilities, frame.width, frame.height, budget); // throws above the limit
    m_links.reallocate(target, frame.capabilities, frame.width, frame.height, budget);
    ++m_regrowthCount;
}

void ABufferLinkedList::render(TrimFrame& frame)
{
    allocate(frame);
    int regrowths = 0;
    m_countedTotal = storePass(frame);
    if (m_countedTotal > m_nodes.capacity()) {
        // Fragments were lost: grow and render the frame again (its counters too).
        grow(m_countedTotal, frame);
        ++regrowths;
        frame.counters.reset();
        m_countedTotal = storePass(frame);
    }
    resolvePass(frame);
    // Per-pixel passes: clears (state and heads) per store, resolve.
    m_stats = {1 + regrowths, 2 * (1 + regrowths) + 1,
               m_state.memoryBytes() + m_head.memoryBytes() + m_nodes.bytes() + m_links.bytes() + sizeof(GLuint), false,
               regrowths};
}

std::uint64_t ABufferLinkedList::storePass(TrimFrame& frame)
{
    clearCountingState(frame, m_state);
    m_head.clear(frame.shaders);
    const GLuint zero = 0;
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_nodeCounter.id());
    m_gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zero), &zero);

    const GLuint program = trimProgram(frame, QStringLiteral("abuffer_list_store"));
    m_gl.glUseProgram(program);
    setClipUniforms(frame, program);
    m_gl.glUniform1ui(m_gl.glGetUniformLocation(program, "u_nodeCapacity"), GLuint(m_nodes.capacity()));
    m_state.bind();
    m_head.bind();
    m_nodes.bind(binding::kNodesStorage, m_nodes.capacity());
    m_links.bind(binding::kLinksStorage, m_links.capacity());
    m_gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::kSharedCountersStorage, m_nodeCounter.id());
    frame.counters.bind();
    beginCapturePass(frame);
    frame.scene.draw(program, frame.projection);
    endCapturePass(frame);
    m_gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                         GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    // CPU-GPU synchronisation: reading the node counter waits for the store pass.
    GLuint stored = 0;
    m_gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m_nodeCounter.id());
    m_gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(stored), &stored);
    return stored;
}

void ABufferLinkedList::resolvePass(TrimFrame& frame)
{
    const GLuint program =
        trimProgram(frame, QStringLiteral("abuffer_list_resolve"), {QStringLiteral("LIST_MAX %1").arg(kRegisterList)});
    m_gl.glUseProgram(program);
    setTrimWalkUniforms(frame, program);
    setOutputUniforms(frame, program);
    setResolveLoopBudget(m_gl, program, frame.capabilities);
    m_state.bind();
    m_head.bind();
    m_nodes.bind(binding::kNodesStorage, m_nodes.capacity());
    m_links.bind(binding::kLinksStorage, m_links.capacity());
    frame.counters.bind();
    drawResolvePass(frame, program);
}

} // namespace trimlab::render
