#pragma once
/// \file
/// AB_FP, the A-buffer with fixed-size per-pixel arrays (thesis 2.4.2, Figure 2.6 a):
/// k slots per pixel (the layers of an RG32UI array texture, as the k⁺-buffer's), filled
/// in order of arrival through an atomic per-pixel counter in one geometry pass
/// (shaders/abuffer_fixed_store.frag), sorted and walked in the resolve
/// (shaders/abuffer_fixed_resolve.frag). Bounded by k: fragments beyond k are lost.
///
/// Overflow rule. The kept fragments are the first k to arrive, not the k nearest, so a
/// trim fragment found among them may be wrong. The store pass records the nearest lost
/// depth of each pixel; every fragment in front of it was kept, so the walk is exact up
/// to there. An overflowed pixel is shown only when its trim fragment lies strictly in
/// front of the nearest lost fragment (provably right); otherwise it is unresolved.

#include "render/gl/gl_objects.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/pixel_state.h"
#include "render/mfr/slot_array.h"

namespace trimlab::render {

class ABufferFixed final : public FragmentMethod {
public:
    explicit ABufferFixed(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::ABufferFixed; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// Fragments held per pixel, min(f(p), k), and the pixels that lost fragments.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override;

private:
    void storePass(TrimFrame& frame);
    void resolvePass(TrimFrame& frame);

    GlFunctions& m_gl;
    PixelState m_state;
    SlotArray m_slots;
    MethodStats m_stats;
};

} // namespace trimlab::render
