#pragma once
/// \file
/// The sort-independent two-pass method of thesis 8.1.2 (Algorithms 8.9 and 8.10): the
/// winding index at the span start as a signed fragment count in one geometry pass, the
/// nearest fragment of the kept span by the hardware depth test in a second, and one step
/// of the shared trim walk in the resolve pass. It shows that fragment when it is a trim
/// boundary. Where it is not — the trim lies deeper, behind an interior sheet of a
/// self-crossing surface — two passes cannot know the answer: the pixel is flagged
/// overflowed and unresolved (counted, magenta), never shown wrong. Hence `bounded` in the
/// catalog: "first layer only".
///
/// Always two geometry passes. Memory: PixelState plus a 32-bit float depth buffer and an
/// RG32UI fragment image of the method's own. Shaders: two_pass_count.frag,
/// two_pass_closest.frag, two_pass_resolve.frag.

#include "render/gl/gl_objects.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/pixel_state.h"

namespace trimlab::render {

class TwoPassTrim final : public FragmentMethod {
public:
    explicit TwoPassTrim(GlFunctions& gl);

    [[nodiscard]] FragmentMethodKind kind() const override { return FragmentMethodKind::TwoPass; }
    void render(TrimFrame& frame) override;
    [[nodiscard]] MethodStats stats() const override { return m_stats; }
    [[nodiscard]] std::optional<std::size_t> estimateBytes(int width, int height,
                                                           const MethodParameters& parameters) const override;
    /// Fragments in each pixel's kept span and the unresolved flags of the last frame.
    [[nodiscard]] std::optional<PixelOccupancy> readOccupancy() override { return m_state.readOccupancy(); }
    [[nodiscard]] static std::size_t requiredBytes(int width, int height);

private:
    void allocate(int width, int height);
    void countPass(TrimFrame& frame);
    void closestPass(TrimFrame& frame);
    void resolvePass(TrimFrame& frame);

    GlFunctions& m_gl;
    PixelState m_state;
    GlFramebuffer m_framebuffer;
    GlTexture m_closest; ///< RG32UI packed fragment, fragment_pack.glsl
    GlTexture m_depth;   ///< DEPTH_COMPONENT32F
    int m_width = 0;
    int m_height = 0;
    MethodStats m_stats;
};

} // namespace trimlab::render
