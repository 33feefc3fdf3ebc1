#pragma once
/// \file
/// Front-to-back depth peeling (F2B, thesis 2.4.2) as a trim method (8.1.2): one fragment
/// of the kept span per pixel and geometry pass, in increasing depth, fed to the shared
/// trim walk until it finds the trim fragment (then the pixel's lock flag stops it).
///
/// Coplanar fragments are not lost: fragments are peeled by the total order of
/// shaders/common/peel_key.glsl — (view depth, object id, primitive id), the CPU
/// reference's walk order — each pass taking the smallest key above the last one peeled.
/// The smallest key is found in two stages with 32-bit image atomics only (atomicMin on
/// the depth bits, then on the order word among the fragments at that depth, counting
/// them: the id ranges of F2B-2P, thesis 6.2.1), pipelined so that each geometry pass
/// finishes one key and starts the next. The first pass counts the winding index and
/// finds the nearest depth, so a pixel whose trim fragment is the n-th of its span needs
/// 1 + n geometry passes, and a frame as many as its slowest pixel.
///
/// Unbounded: nothing is lost unless MethodParameters::maxPeelingPasses stops the frame;
/// the pixels still peeling then are flagged unresolved. Passes and termination:
/// mfr/peeling_passes.h. Shaders: peel_f2b.frag, peel_f2b_walk.frag, peeling_resolve.frag.

#include "render/mfr/fragment_method.h"
#include "render/mfr/peeling_passes.h"
#include "render/mfr/peeling_state.h"

namespace trimlab::render {

class F2BPeeling final : public FragmentMethod {
public:
    explicit F2BPeeling(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::PeelingF2B; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    /// A fixed number of bytes per pixel (PeelingState::bytesPerPixel(false)).
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// Fragments peeled per pixel and the unresolved flags of the last frame.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }

private:
    PeelingState m_state;
    PeelingPasses m_passes;
    MethodStats m_stats;
};

} // namespace trimlab::render
