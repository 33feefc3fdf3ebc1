#pragma once
/// \file
/// Per-frame counters the shaders increment (an atomic counter buffer; the layout is in
/// shaders/common/kplus_images.glsl): how many fragments were stored, how many pixels
/// overflowed or could not be resolved, how many fragments gave up waiting for a lock.

#include "gl/gl_functions.h"
#include "gl/gl_objects.h"

#include <cstdint>

namespace trimlab::render {

struct FrameCounts {
    std::uint64_t fragmentsInSpan = 0;  ///< fragments inside the kept span (after clipping)
    std::uint64_t overflowPixels = 0;   ///< pixels that received more than k fragments
    std::uint64_t unresolvedPixels = 0; ///< overflowed pixels whose trim point lies beyond k
    std::uint64_t spinGiveUps = 0;      ///< fragments dropped after the bounded spin-lock
};

class FrameCounters {
public:
    static constexpr GLuint kBinding = 0;

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
