#pragma once
/// \file
/// What the GPU reports of a frame — its GL_TIME_ELAPSED and its counters
/// (frame_counters.h) — read a frame or more after the frame was issued, so that the CPU
/// prepares the next frame while the GPU draws this one. A small ring of slots, each a
/// time query, a copy of the counters and a fence: a frame takes the next slot; poll()
/// hands back what the GPU has finished without waiting; wait() waits for every frame
/// still pending (a batch verb, a benchmark or a readback that needs this frame's
/// numbers).

#include "render/frame/frame_counters.h"
#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <array>
#include <cstdint>
#include <vector>

namespace trimlab::render {

/// One frame's results as the GPU delivered them.
struct FrameResult {
    std::uint64_t serial = 0; ///< the frame's number given to begin()
    FrameCounts counts;
    GLuint64 elapsedNs = 0; ///< GL_TIME_ELAPSED (llvmpipe may answer garbage for a context's first)
};

class FrameResultRing {
public:
    /// Frames the GPU may run behind the CPU before begin() waits for the oldest.
    static constexpr std::size_t kSlots = 4;

    explicit FrameResultRing(GlFunctions& gl);
    ~FrameResultRing();
    FrameResultRing(const FrameResultRing&) = delete;
    FrameResultRing& operator=(const FrameResultRing&) = delete;

    /// Starts timing frame `serial` in the next slot. When every slot still waits for the
    /// GPU, first waits for the oldest (a GPU wait) and appends its result to `finished`.
    void begin(std::uint64_t serial, std::vector<FrameResult>& finished);
    /// Ends the frame begun last: stops its time query, copies `counters` and fences it,
    /// and flushes so that the GPU starts on it.
    void end(FrameCounters& counters);
    /// Results of the frames the GPU has finished, oldest first; never waits.
    [[nodiscard]] std::vector<FrameResult> poll();
    /// Results of every pending frame, oldest first; waits for the GPU.
    [[nodiscard]] std::vector<FrameResult> wait();

private:
    struct Slot {
        GlQuery query;
        GlBuffer counters;
        GLsync fence = nullptr;
        std::uint64_t serial = 0;
    };

    [[nodiscard]] Slot& oldest() { return m_slots[(m_next + kSlots - m_pendingCount) % kSlots]; }
    /// The oldest pending slot's result if the GPU delivered it; with `block`, waits.
    [[nodiscard]] bool collectOldest(bool block, std::vector<FrameResult>& results);

    GlFunctions& m_gl;
    std::array<Slot, kSlots> m_slots;
    std::size_t m_next = 0;         ///< the slot the next begin() takes
    std::size_t m_pendingCount = 0; ///< slots ended and not yet collected
    bool m_begun = false;           ///< begin() without its end() yet
};

} // namespace trimlab::render
