#pragma once
/// \file
/// Per-frame counters the shaders increment (an atomic counter buffer; the layout is in
/// shaders/common/frame_counters.glsl): fragments in the span, stored and lost, pixels
/// that overflowed or could not be resolved, fragments that gave up waiting for a lock.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

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
    explicit FrameCounters(GlFunctions& gl);
    void reset();
    void bind();
    /// Reads the counters back (waits for the GPU).
    [[nodiscard]] FrameCounts read();

private:
    GlFunctions& m_gl;
    GlBuffer m_buffer;
};

} // namespace trimlab::render
