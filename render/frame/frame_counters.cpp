#include "render/frame/frame_counters.h"

#include "render/gl/bindings.h"

#include <array>

namespace trimlab::render {

namespace {
constexpr std::size_t kCounterCount = 9;
}

FrameCounters::FrameCounters(GlFunctions& gl) : m_gl(gl), m_buffer(gl)
{
    m_gl.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, m_buffer.id());
    m_gl.glBufferData(GL_ATOMIC_COUNTER_BUFFER, kCounterCount * sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
    checkAllocation(m_gl, "frame counters", kCounterCount * sizeof(GLuint));
    reset();
}

void FrameCounters::reset()
{
    const std::array<GLuint, kCounterCount> zeros{};
    m_gl.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, m_buffer.id());
    m_gl.glBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof(zeros), zeros.data());
}

void FrameCounters::bind()
{
    m_gl.glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, binding::kFrameCountersAtomic, m_buffer.id());
}

FrameCounts FrameCounters::read()
{
    std::array<GLuint, kCounterCount> values{};
    m_gl.glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    m_gl.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, m_buffer.id());
    m_gl.glGetBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof(values), values.data());
    return {values[0], values[1], values[2], values[3], values[4], values[5], values[6], values[7], values[8]};
}

} // namespace trimlab::render
