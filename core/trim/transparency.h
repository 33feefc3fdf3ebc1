#pragma once
/// \file
/// Front-to-back compositing of a pixel's X-ray layers (TransparencySettings in
/// inspect_settings.h says which fragments are layers). The GLSL twin is
/// shaders/common/transparency.glsl; keep the two identical in their sequence of
/// operations (the render tests compare GPU colors with the CPU reference, which uses
/// compositeXray in double precision).
///
/// The sequence for one pixel ray, all distances in world units from the eye:
///  1. start with C = 0, T = 1, d = the span start;
///  2. a cap (when shown): Opaque → the pixel is the cap's color; Translucent → composite
///     it with alpha fresnelAlpha(layerAlpha, |n·v|, p);
///  3. for every fragment of the kept span in walk order, while T >= kXrayStopTransmittance:
///     if the interval in front of it classifies interior, T *= exp(−density·(depth − d));
///     d = depth; then composite it with the alpha of its role (xrayAlpha); an Opaque
///     role ends the walk;
///  4. the pixel is C + T·background.

#include "core/trim/inspect_settings.h"

#include <glm/vec3.hpp>

#include <optional>
#include <span>

namespace trimlab {

/// Compositing stops once the transmittance drops below this: what lies behind can change
/// no channel by more than half a step of 8 bits.
inline constexpr double kXrayStopTransmittance = 1.0 / 512.0;

/// What one fragment contributes.
enum class XrayRole {
    Hidden, ///< nothing (alpha 0)
    Ghost,  ///< a removed fragment, alpha ghostAlpha
    Layer,  ///< a boundary of the trimmed solid, alpha layerAlpha (Translucent)
    Opaque, ///< the first boundary in Opaque display: alpha 1, ends the walk
};

/// The role of a fragment: `boundary` — its two sides classify differently (always true
/// with trimming off); `shownBefore` — a boundary (or a cap) lies in front of it.
[[nodiscard]] XrayRole xrayRole(const TransparencySettings& settings, bool boundary, bool shownBefore);

/// alpha + (1 − alpha)(1 − |cosine|)^exponent, with alpha clamped to [0, 1]; alpha
/// itself when exponent <= 0 (Fresnel off) or alpha <= 0 (hidden stays hidden).
/// Non-finite inputs count as 0.
[[nodiscard]] double fresnelAlpha(double alpha, double cosine, double exponent);

/// The alpha of `role` for a surface seen at |n·v| = `cosine`.
[[nodiscard]] double xrayAlpha(const TransparencySettings& settings, XrayRole role, double cosine);

/// Running state of the compositing.
struct XrayAccumulator {
    glm::dvec3 color{0.0};
    double transmittance = 1.0;
    double lastDepth = 0.0; ///< where the last density interval ended

    [[nodiscard]] bool done() const { return transmittance < kXrayStopTransmittance; }
};

/// C += T·alpha·color; T *= 1 − alpha.
void compositeLayer(XrayAccumulator& accumulator, const glm::dvec3& color, double alpha);
/// Beer–Lambert over [lastDepth, depth] when `interior`: T *= exp(−density·(depth −
/// lastDepth)) (density <= 0 or non-finite: no change); lastDepth = depth either way.
void crossInterval(XrayAccumulator& accumulator, double density, double depth, bool interior);

/// One fragment of the kept span as the walk passed it.
struct XrayFragment {
    double depth = 0.0;          ///< world distance from the eye along the ray
    bool boundary = false;       ///< the two sides classify differently
    bool interiorBefore = false; ///< the interval in front of it classifies interior
    glm::dvec3 color{0.0};       ///< its shaded color (with highlights for the first boundary)
    double cosine = 1.0;         ///< |n·v| at it
};

/// A cap at the span start.
struct XrayCap {
    glm::dvec3 color{0.0};
    double cosine = 1.0;
};

/// The pixel's color after the sequence above. `startDepth`: world distance of the span
/// start; `fragments` in walk order (may hold fragments beyond the stop: they are ignored).
[[nodiscard]] glm::dvec3 compositeXray(const TransparencySettings& settings, double startDepth,
                                       const std::optional<XrayCap>& cap, std::span<const XrayFragment> fragments,
                                       const glm::dvec3& background);

} // namespace trimlab
