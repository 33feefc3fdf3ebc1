#pragma once
/// \file
/// Per-frame counters the shaders increment (an atomic counter buffer; the layout is in
/// shaders/common/frame_counters.glsl): fragments in the span, stored and lost, pixels
/// that overflowed or could not be resolved, fragments that gave up waiting for a lock.
/// The CPU reads them a frame or more later (frame_results.h): reset and copy are GPU
/// commands, so the frame that increments them never waits for them.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <array>
#include <cstdint>

namespace trimlab::render {

/// Layout: shaders/common/frame_counters.glsl.
struct FrameCounts {
    std::uint64_t fragmentsInSpan = 0;  ///< fragments inside the kept span (after clipping)
    std::uint64_t overflowPixels = 0;   ///< pixels that lost fragments to a capacity limit
    std::uint64_t unresolvedPixels = 0; ///< of those, pixels whose trim point may have been lost
    std::uint64_t spinGiveUps = 0;      ///< fragments dropped after the bounded spin-lock
    std::uint64_t fragmentsLost = 0;    ///< fragments not stored (capacity, spin give-ups)
    std::uint64_t fragmentsStored = 0;  ///< fragments written to the method's storage
    std::uint64_t capPixels = 0;        ///< pixels showing a cap (CapSettings)
    std::uint64_t collisionPixels = 0;  ///< shown fragments highlighted as colliding (the UI's status bar)
    std::uint64_t coplanarPixels = 0;   ///< shown fragments in a coplanar group of 2 or more
};

class FrameCounters {
public:
    static constexpr std::size_t kCount = 9;
    using Values = std::array<GLuint, kCount>;
    static constexpr std::size_t kBytes = sizeof(Values);

    explicit FrameCounters(GlFunctions& gl);
    /// Zeroes the counters (a GPU command).
    void reset();
    void bind();
    /// Copies the counters into `buffer` (at least kBytes) once the frame's shaders have
    /// written them (a GPU command).
    void copyTo(GLuint buffer);
    /// The counts of values copied back.
    [[nodiscard]] static FrameCounts decode(const Values& values);

private:
    GlFunctions& m_gl;
    GlBuffer m_buffer;
};

} // namespace trimlab::render
