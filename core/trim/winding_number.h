#pragma once
/// \file
/// The winding index w(p, M) of thesis 2.1 computed without rays: the signed solid angle
/// that the scene's triangles subtend at p, divided by 4π (the generalized winding
/// number). For a closed oriented surface and p off the surface it is an integer; it is an
/// independent check of ray-counted indices (tests) and works for any point.

#include "core/scene/scene.h"

#include <glm/vec3.hpp>

namespace trimlab {

/// Σ over all triangles of all objects (world space) of the signed solid angle at `p`
/// (Van Oosterom–Strackee), / 4π. Triangles counter-clockwise seen from outside count +1
/// for points inside. Not rounded: ≈ an integer away from the surface, ill-conditioned
/// within rounding distance of it; undefined on it. O(#triangles).
[[nodiscard]] double solidAngleWindingNumber(const Scene& scene, const glm::dvec3& p);

} // namespace trimlab
