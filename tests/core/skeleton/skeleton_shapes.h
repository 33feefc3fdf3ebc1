#pragma once
// Generated closed meshes for the skeleton-extraction tests: a capsule whose axis is known,
// and a 'star' of capsules fused at a central sphere, meshed watertight from an implicit
// function by marching tetrahedra (written here; see skeleton_shapes.cpp).
#include "core/mesh/triangle_mesh.h"

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace trimlab::test {

// A capsule around the y axis: cylinder of `radius` over y ∈ [−halfLength, halfLength],
// hemispherical caps of `capRings` bands, `bodyRings` bands along the cylinder, `segments`
// vertices around. Closed, manifold, outward (a surface of revolution).
[[nodiscard]] TriangleMesh axisCapsule(double radius, double halfLength, int capRings, int bodyRings, int segments);

// The zero level set of `f` (negative inside) over the box [lower, upper], sampled on a grid
// of cubes of edge `cell`, each split into 6 tetrahedra around its main diagonal (the same
// split in every cube, so neighbouring tetrahedra share faces). Linear interpolation along
// tetrahedron edges; vertices on a grid edge are shared by every tetrahedron around it, so
// the surface is closed and manifold (values within 1e-3·cell of zero are moved to
// +1e-3·cell so no node lies on it). Triangles face outward (towards increasing f). `f`
// must be positive on the box's boundary.
[[nodiscard]] TriangleMesh marchingTetrahedra(const std::function<double(const glm::dvec3&)>& f,
                                              const glm::dvec3& lower, const glm::dvec3& upper, double cell);

// A star in the plane y = 0: a sphere of `hubRadius` at the origin and one capsule
// (radius `armRadius`) per entry of `armLengths`, from the origin to the tip at distance
// armLengths[k] + armRadius in direction armDirection(k, #arms), blended by a smooth
// minimum (blend radius armRadius/2). Negative inside; ≈ the signed distance away from the
// blend.
struct Star {
    double hubRadius = 0.45;
    double armRadius = 0.2;
    std::vector<double> armLengths{1.4, 1.7, 1.5};

    [[nodiscard]] glm::dvec3 armDirection(std::size_t k) const;
    [[nodiscard]] double implicit(const glm::dvec3& p) const;
    [[nodiscard]] TriangleMesh mesh(double cell) const;
};

// A fork in the plane y = 0: a handle (capsule of `handleRadius` from (−handleLength, 0, 0)
// to the origin), a stem (capsule of `prongRadius` from the origin to (stemLength, 0, 0))
// and two prongs of `prongRadius` from the stem's end, `prongLength` long, `spread` radians
// to either side of the x axis; blended by a smooth minimum (blend radius prongRadius/2).
struct Fork {
    double handleRadius = 0.3;
    double handleLength = 1.2;
    double prongRadius = 0.15;
    double stemLength = 0.5;
    double prongLength = 1.0;
    double spread = 0.6;

    [[nodiscard]] glm::dvec3 prongTip(int side) const; ///< side −1 or +1: the end of its axis
    [[nodiscard]] double implicit(const glm::dvec3& p) const;
    [[nodiscard]] TriangleMesh mesh(double cell) const;
};

} // namespace trimlab::test
