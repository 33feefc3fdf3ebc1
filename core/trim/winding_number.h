#pragma once
/// \file
/// The winding index w(p, M) of thesis 2.1 computed without rays: the signed solid angle
/// that the scene's triangles subtend at p, divided by 4π (the generalized winding
/// number). For a closed oriented surface and p off the surface it is an integer; it is an
/// independent check of ray-counted indices (tests) and works for any point.

#include "core/scene/scene.h"

#include <glm/vec3.hpp>

namespace trimlab {

/// The signed solid angle (steradians, in [−2π, 2π]) of the triangle with corners a, b, c
/// seen from the origin (Van Oosterom–Strackee): positive when the normal (b−a)×(c−a) points
/// away from the origin, as it does for a point inside a solid whose triangles are
/// counter-clockwise seen from outside.
[[nodiscard]] double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

/// Σ over all triangles of all objects (world space) of the signed solid angle at `p`
/// (Van Oosterom–Strackee), / 4π. Triangles counter-clockwise seen from outside count +1
/// for points inside. Not rounded: ≈ an integer away from the surface, ill-conditioned
/// within rounding distance of it; undefined on it. O(#triangles).
[[nodiscard]] double solidAngleWindingNumber(const Scene& scene, const glm::dvec3& p);

} // namespace trimlab
