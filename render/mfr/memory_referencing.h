#pragma once
/// \file
/// The S-buffer's precise allocation (thesis 5.1.1–5.1.2), shared by the S-buffer and
/// K⁺B-SB (7.1.3): a fragment count pass, then memory referencing with S shared counters.
///
/// 1. Count pass (geometry): f(p), the fragments of each pixel's kept span, in the
///    counter image; the exact winding index; the frame's fragmentsInSpan.
/// 2. Referencing (three compute dispatches, shaders/sbuffer_*.comp): every non-empty
///    pixel takes n(p) = min(f(p), regionLimit) nodes from the counter of its hash group
///    H(p) = (x + width·y) mod S (equation 5.1); a forward prefix sum over the first half
///    of the counters and an inverse one over the second half give each group its memory
///    (the thesis's inverse mapping), and the total; each pixel's region start follows
///    from equation 5.2. The counter restarts at 0 for the store pass and pixels with
///    f(p) > regionLimit are flagged overflowed.
///
/// Detail decided here: the thesis gives a G2 pixel the offset total − 1 − A(p), the last
/// node of its region, filled downwards; TrimLab stores the region's first node,
/// total − A(p) − n(p), so every pixel's region is [head, head + n) and the store and
/// resolve passes need not know the pixel's group.

#include "render/gl/gl_functions.h"
#include "render/gl/gl_objects.h"

#include <cstddef>
#include <cstdint>

namespace trimlab::render {

class HeadImage;
class PixelState;
struct TrimFrame;

class MemoryReferencing {
public:
    explicit MemoryReferencing(GlFunctions& gl);

    /// The fragment count pass. `state` must be cleared; its counter, winding and the
    /// frame counters are bound here.
    void countPass(TrimFrame& frame, PixelState& state);

    /// Referencing for `sharedCounters` = S counters (in the range of
    /// method_parameters::kSharedCounters, else std::invalid_argument). Returns Σ_p n(p), the nodes the frame needs, read back to
    /// the CPU: this waits for the GPU to finish the count and referencing passes (the
    /// one CPU–GPU synchronisation of a counted method's frame, needed to size the node
    /// buffer). Afterwards the head image holds each pixel's region start.
    std::uint64_t reference(TrimFrame& frame, PixelState& state, HeadImage& head, int sharedCounters,
                            std::uint32_t regionLimit);

    [[nodiscard]] std::size_t memoryBytes() const { return m_counterBytes; }

private:
    void allocateCounters(int sharedCounters);
    GLuint useReferencingProgram(TrimFrame& frame, const char* name, std::uint32_t regionLimit);

    GlFunctions& m_gl;
    GlBuffer m_counters;
    std::size_t m_counterBytes = 0;
    int m_sharedCounters = 0;
};

} // namespace trimlab::render
