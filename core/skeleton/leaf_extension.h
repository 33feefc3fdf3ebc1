#pragma once
/// \file
/// Leaf extension, so that a limb's tip has a bone near it. Contraction shrinks every limb
/// along its length as well as across it, and the simplification's pre-collapse merges the
/// last sections, so a curve skeleton's leaf ends about a limb's width short of the tip:
/// the vertices of the tip are then the farthest from any bone. Each leaf here moves
/// outward along its edge's direction until it is one local radius short of the farthest
/// vertex of its region (the tip's cap), as far as the extension stays inside the solid.
/// The local radius is the mean distance of the region's vertices from the edge's line.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

/// How far a region reaches ahead of a point along a direction, and how wide it is there.
struct RegionReach {
    double ahead = 0.0;  ///< the largest projection of a vertex on the direction (0 when none is ahead)
    double radius = 0.0; ///< the vertices' mean distance from the line through the point
};

/// RegionReach of the vertices `region` of `mesh` from `from` along the unit `direction`
/// (`region` not empty). The extension's length is ahead − radius: one local radius short
/// of the tip.
[[nodiscard]] RegionReach regionReach(const std::vector<std::size_t>& region, const TriangleMesh& mesh,
                                      const glm::dvec3& from, const glm::dvec3& direction);

/// Per node of `curve`: its one neighbour when it is a leaf (degree 1), else −1.
[[nodiscard]] std::vector<int> leafNeighbours(const CurveSkeleton& curve);

/// Moves the leaves (nodes of degree 1 with a non-empty region) of `curve` as described
/// above. `mesh` holds the regions' original positions. Returns the leaves moved.
std::size_t extendLeaves(CurveSkeleton& curve, const TriangleMesh& mesh, const PointInMesh& solid);

} // namespace trimlab
