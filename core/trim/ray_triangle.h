#pragma once
/// \file
/// Watertight ray–triangle intersection in double precision (after Woop, Benthin and Wald,
/// "Watertight Ray/Triangle Intersection", JCGT 2013), with an exact tie-break for rays
/// through shared edges and vertices so a closed mesh is crossed exactly once per sheet.
///
/// How it works: the ray's dominant axis becomes z; every vertex is translated to the ray
/// origin and sheared so the ray is the +z axis. A vertex's sheared 2D position depends
/// only on the vertex and the ray, so triangles sharing it see bitwise identical numbers.
/// The 2D edge functions U, V, W (opposite vertices a, b, c) get exact signs (a floating
/// filter, then an exact expansion where the filter cannot decide). A triangle is hit iff
/// its edge functions do not have opposite signs and, for each edge function that is
/// exactly zero, that edge passes the half-plane tie-break of `ownsZeroEdge`. The tie-break
/// equals moving the ray by an infinitesimal fixed 2D offset (ε, ε²), so on any mesh whose
/// projection covers a neighbourhood of the ray once per sheet (shared edges, vertex fans)
/// exactly one triangle per sheet is hit — the winding index is never off by one.

#include "core/view/camera.h"

#include <glm/vec3.hpp>

#include <optional>

namespace trimlab {

/// Per-ray constants of the watertight test. Build once per ray with makeWatertightRay.
struct WatertightRay {
    glm::dvec3 origin{0.0};
    int kx = 0; ///< axis that becomes 2D x
    int ky = 1; ///< axis that becomes 2D y
    int kz = 2; ///< dominant axis of the direction
    double shearX = 0.0;
    double shearY = 0.0;
    double scaleZ = 1.0;
};

/// Precomputes the axis permutation and shear for `ray`. The direction must be finite and
/// non-zero (a zero direction gives a ray that hits nothing, with t undefined).
[[nodiscard]] WatertightRay makeWatertightRay(const PixelRay& ray);

/// A hit of one triangle, before object/primitive ids are attached (see RayHit).
/// `t`: ray parameter (may be negative: the caller filters the range);
/// `facing`: +1 front-facing (counter-clockwise seen from the ray origin), −1 back-facing;
/// `u`, `v`: barycentric weights of b and c (point = (1−u−v)a + u b + v c).
struct TriangleHit {
    double t = 0.0;
    int facing = 0;
    double u = 0.0;
    double v = 0.0;
};

/// Intersects the ray with triangle (a, b, c) in world space. Returns nullopt on a miss,
/// for triangles seen exactly edge-on (zero projected area) and for non-finite input.
/// Facing is taken from the signs of the projected edge functions, which is the exact sign
/// of −dot((b−a)×(c−a), direction) evaluated on the sheared vertices (no cancellation).
[[nodiscard]] std::optional<TriangleHit> intersectTriangle(const WatertightRay& ray, const glm::dvec3& a,
                                                           const glm::dvec3& b, const glm::dvec3& c);

/// Exact sign (−1, 0, +1) of p·q − r·s for finite doubles (no overflow or underflow in
/// the products). Exposed for tests.
[[nodiscard]] int exactSignOfDifferenceOfProducts(double p, double q, double r, double s);

/// The tie-break for an edge function that is exactly zero: the edge from `from` to `to`
/// (2D sheared coordinates, oriented so the triangle's inside has positive edge functions)
/// owns the ray iff dy > 0, or dy == 0 and dx < 0. Exposed for tests.
[[nodiscard]] bool ownsZeroEdge(double fromX, double fromY, double toX, double toY);

} // namespace trimlab
