#include "render/frame/frame_counters.h"

#include "render/gl/bindings.h"

namespace trimlab::render {

FrameCounters::FrameCounters(GlFunctions& gl) : m_gl(gl), m_buffer(gl)
{
    m_gl.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, m_buffer.id());
    m_gl.glBufferData(GL_ATOMIC_COUNTER_BUFFER, kBytes, nullptr, GL_DYNAMIC_COPY);
    checkAllocation(m_gl, "frame counters", kBytes);
    reset();
}

void FrameCounters::reset()
{
    const GLuint zero = 0;
    m_gl.glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, m_buffer.id());
    m_gl.glClearBufferSubData(GL_ATOMIC_COUNTER_BUFFER, GL_R32UI, 0, kBytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void FrameCounters::bind()
{
    m_gl.glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, binding::kFrameCountersAtomic, m_buffer.id());
}

void FrameCounters::copyTo(GLuint buffer)
{
    m_gl.glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    m_gl.glBindBuffer(GL_COPY_READ_BUFFER, m_buffer.id());
    m_gl.glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
    m_gl.glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, kBytes);
}

FrameCounts FrameCounters::decode(const Values& values)
{
    return {values[0], values[1], values[2], values[3], values[4], values[5], values[6], values[7], values[8]};
}

} // namespace trimlab::render
