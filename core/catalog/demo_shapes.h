#pragma once
/// \file
/// The self-crossing shapes of the demo scenes, with their resolution exposed so tests and
/// benchmarks can make coarser or finer versions. Deterministic; all outward oriented.

#include "core/mesh/triangle_mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace trimlab {

/// Shape constants of the pushed sphere (unit sphere centred at the origin, axis y).
struct PushedSphereShape {
    static constexpr double fingerRadius = 0.3;   ///< radius of the pushed-in finger
    static constexpr double rimRadius = 0.6;      ///< where the finger's lip meets the sphere
    static constexpr double fingerTipY = -1.6;    ///< lowest point of the finger (on the axis)
    static constexpr double fingerBottomY = -1.3; ///< where the finger wall meets its round tip
    static constexpr double lipBottomY = 0.6;     ///< where the lip meets the finger wall
};

/// Meridian (r, y) of the pushed sphere, in makeSurfaceOfRevolution's convention (solid
/// on the left): from the south pole (0, −1) up the unit sphere to the rim (0.6, 0.8),
/// round a smooth lip (cubic Bézier) into the finger wall r = 0.3, down the wall through
/// the sphere's south cap (the self-crossing, at y = −√0.91) to y = −1.3, and round the
/// hemispherical tip to (0, −1.6). `samples` (>= 8, else clamped) points, spaced evenly
/// in arc length + 0.5 · turning angle, so curved parts are sampled more densely.
[[nodiscard]] std::vector<glm::dvec2> pushedSphereProfile(int samples);

/// Thesis Fig. 1.2 / 8.3 in spirit: a unit sphere whose north cap was pushed down as a
/// finger through its own south cap. Winding index: 1 in the sphere's body, 0 inside the
/// finger within the sphere, −1 inside the part of the finger below the sphere. Under the
/// alternating border rule the south cap inside the finger and the protruding finger are
/// trimmed: a hole through the sphere (genus 0 → 1). Triangles: 2·segments·(samples − 2).
[[nodiscard]] TriangleMesh makePushedSphere(int segments = 96, int profileSamples = 40);

/// Closed planar figure-eight (Gerono lemniscate) in the plane y = 0:
/// (1.6 cos s, 0, 0.7 sin 2s), s = 2πi/samples, crossing itself at the origin at ~97°.
/// Its smallest radius of curvature is ~0.46. `samples` >= 8 (else clamped).
[[nodiscard]] std::vector<glm::dvec3> lemniscateCurve(int samples);

/// A tube of radius 0.3 swept along lemniscateCurve: an immersed torus (genus 1) that
/// passes through itself at the crossing, where the winding index is 2.
/// Triangles: 2·curveSamples·sides.
[[nodiscard]] TriangleMesh makeCrossingLoop(int curveSamples = 160, int sides = 24);

} // namespace trimlab
