#pragma once
/// \file
/// Dual depth peeling (DUAL, thesis 2.4.2) as a trim method (8.1.2): per geometry pass the
/// nearest and the farthest unpeeled fragment of each pixel's kept span, the min-max
/// search done on the exact keys of shaders/common/peel_key.glsl (so coincident
/// fragments are peeled one by one, as DUAL-2P does in thesis 6.2.2) with the pipelined
/// two-stage atomics of F2B (mfr/f2b_peeling.h) in both directions.
///
/// The trim walk needs the fragments from the span start, but the winding index is known
/// exactly at both ends of the span, so the back layers feed a second walk from the far
/// end (shaders/common/trim_walk_backward.glsl). The front walk decides as soon as it
/// finds a boundary; otherwise the answer is the nearest boundary the back walk found,
/// known once the two walks meet. Where the trim lies deep or is absent, DUAL needs about
/// half of F2B's passes; where it is near the front, the same number.
///
/// Unbounded, with F2B's pass bound, lock flags and termination (mfr/peeling_passes.h).
/// Shaders: peel_dual.frag, peel_dual_walk.frag, peeling_resolve.frag.

#include "render/mfr/fragment_method.h"
#include "render/mfr/peeling_passes.h"
#include "render/mfr/peeling_state.h"

namespace trimlab::render {

class DualPeeling final : public FragmentMethod {
public:
    explicit DualPeeling(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::PeelingDual; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    /// A fixed number of bytes per pixel (PeelingState::bytesPerPixel(true)).
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// Fragments peeled per pixel (from both ends) and the unresolved flags of the last frame.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }

private:
    PeelingState m_state;
    PeelingPasses m_passes;
    MethodStats m_stats;
};

} // namespace trimlab::render
