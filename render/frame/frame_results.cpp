#include "render/frame/frame_results.h"

#include <stdexcept>

namespace trimlab::render {

FrameResultRing::FrameResultRing(GlFunctions& gl) : m_gl(gl)
{
    for (Slot& slot : m_slots) {
        slot.query = GlQuery(gl);
        slot.counters = GlBuffer(gl);
        m_gl.glBindBuffer(GL_COPY_WRITE_BUFFER, slot.counters.id());
        m_gl.glBufferData(GL_COPY_WRITE_BUFFER, FrameCounters::kBytes, nullptr, GL_STREAM_READ);
    }
    checkAllocation(m_gl, "frame result copies", double(kSlots * FrameCounters::kBytes));
}

FrameResultRing::~FrameResultRing()
{
    for (Slot& slot : m_slots)
        if (slot.fence)
            m_gl.glDeleteSync(slot.fence);
}

void FrameResultRing::begin(std::uint64_t serial, std::vector<FrameResult>& finished)
{
    if (m_begun)
        throw std::logic_error("FrameResultRing::begin: the previous frame was not ended.");
    if (m_pendingCount == kSlots)
        (void)collectOldest(true, finished);
    Slot& slot = m_slots[m_next];
    slot.serial = serial;
    m_gl.glBeginQuery(GL_TIME_ELAPSED, slot.query.id());
    m_begun = true;
}

void FrameResultRing::end(FrameCounters& counters)
{
    if (!m_begun)
        throw std::logic_error("FrameResultRing::end without begin.");
    Slot& slot = m_slots[m_next];
    m_gl.glEndQuery(GL_TIME_ELAPSED);
    counters.copyTo(slot.counters.id());
    if (slot.fence)
        m_gl.glDeleteSync(slot.fence);
    slot.fence = m_gl.glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    m_gl.glFlush();
    m_begun = false;
    m_next = (m_next + 1) % kSlots;
    ++m_pendingCount;
}

bool FrameResultRing::collectOldest(bool block, std::vector<FrameResult>& results)
{
    Slot& slot = oldest();
    FrameCounters::Values values{};
    FrameResult result;
    result.serial = slot.serial;
    m_gl.glBindBuffer(GL_COPY_READ_BUFFER, slot.counters.id());
    if (block) {
        m_gl.glClientWaitSync(slot.fence, GL_SYNC_FLUSH_COMMANDS_BIT, ~GLuint64(0));
        m_gl.glGetBufferSubData(GL_COPY_READ_BUFFER, 0, FrameCounters::kBytes, values.data());
        m_gl.glGetQueryObjectui64v(slot.query.id(), GL_QUERY_RESULT, &result.elapsedNs);
    } else {
        // The fence follows the query's end, so a passed fence means both are in; the query
        // is still asked whether its answer is there rather than trusted to be.
        if (!m_gl.fencePassed(slot.fence) || !m_gl.tryQueryResult(slot.query.id(), result.elapsedNs) ||
            !m_gl.tryReadBuffer(slot.fence, GL_COPY_READ_BUFFER, 0, FrameCounters::kBytes, values.data()))
            return false;
    }
    result.counts = FrameCounters::decode(values);
    results.push_back(result);
    --m_pendingCount;
    return true;
}

std::vector<FrameResult> FrameResultRing::poll()
{
    std::vector<FrameResult> results;
    while (m_pendingCount > 0 && collectOldest(false, results)) {
    }
    return results;
}

std::vector<FrameResult> FrameResultRing::wait()
{
    std::vector<FrameResult> results;
    while (m_pendingCount > 0)
        (void)collectOldest(true, results);
    return results;
}

} // namespace trimlab::render
