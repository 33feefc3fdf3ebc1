#pragma once
/// \file
/// One brush stroke of the designer workflow (thesis 8.2: a magnet-like linear space warp
/// with geodesic range and angle-weighted attenuation, followed by iterative Laplacian
/// smoothing and weighted normal recomputation). A stroke is complete data: applying the
/// same stroke to the same positions gives bit-identical results, which is what the
/// timeline, the project file, undo and stroke scripts rely on.

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string_view>

namespace trimlab::deform {

/// Shape of the falloff f(d/r) of the displacement with geodesic distance d within the
/// radius r: 1 at the anchor, 0 at and beyond the radius, monotone non-increasing.
enum class FalloffProfile {
    Smooth, ///< C¹ bell, zero slope at both ends
    Linear, ///< 1 − d/r
    Sharp,  ///< concentrated near the anchor (fast decay)
};

/// Weights of the Laplacian smoothing that follows the warp.
enum class SmoothingWeights {
    Uniform,   ///< umbrella operator: average of the one-ring
    Cotangent, ///< cotangent weights (clamped non-negative), shape-aware
};

/// What the Brush panel sets. Units: object-space lengths (the mesh's own units).
struct BrushSettings {
    double radius = 0.25;  ///< geodesic radius of influence (> 0)
    double strength = 1.0; ///< scales the drag (1: the anchor follows the drag)
    FalloffProfile profile = FalloffProfile::Smooth;
    int smoothingIterations = 2; ///< Laplacian iterations restricted to the influenced region (>= 0)
    SmoothingWeights smoothingWeights = SmoothingWeights::Uniform;
    double smoothingStep = 0.5; ///< λ of p ← p + λ·L(p), in (0, 1]

    friend bool operator==(const BrushSettings&, const BrushSettings&) = default;
};

/// A committed stroke: where it grabbed the surface and how far it was dragged.
struct Stroke {
    /// The grabbed surface point (object space). When `anchorTriangle` is set it lies on
    /// that triangle; when not, the stroke grabs the closest point of the surface to it
    /// (how scripts written by hand give it).
    glm::dvec3 anchor{0.0};
    std::optional<std::uint32_t> anchorTriangle;
    /// Displacement of the anchor (object space) before `strength` scales it.
    glm::dvec3 drag{0.0};
    BrushSettings brush;

    friend bool operator==(const Stroke&, const Stroke&) = default;
};

[[nodiscard]] std::string_view falloffProfileName(FalloffProfile profile); ///< "smooth", "linear", "sharp"
[[nodiscard]] std::optional<FalloffProfile> parseFalloffProfile(std::string_view name);
[[nodiscard]] std::string_view smoothingWeightsName(SmoothingWeights weights); ///< "uniform", "cotangent"
[[nodiscard]] std::optional<SmoothingWeights> parseSmoothingWeights(std::string_view name);

} // namespace trimlab::deform
