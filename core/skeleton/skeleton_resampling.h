#pragma once
/// \file
/// Resampling of the refined curve skeleton, so that its nodes and edges are inside and
/// centred. The simplification leaves as few nodes as the contracted mesh had sections
/// that survived the collapses: on a bent limb an edge can span a whole knee, and the
/// straight segment between two centred nodes then runs off the axis or out of the solid.
/// Here every edge longer than `spacing` is cut into equal steps no longer than it, and
/// each new node goes to the centre of its slice of the surface: the region vertices of
/// the edge's two nodes are assigned to the edge they lie along (the incident edge nearest
/// to them, on their node's half of it), sliced by their projection on the edge, and a
/// slice's node is the mean of its vertices' inward chord midpoints
/// (skeleton_refinement.h) — the centre of that cross-section. The slice's vertices move to
/// the new node's region, so the regions stay a partition of the mesh's vertices.
/// Last, an edge that still leaves the solid (a bend sharper than the spacing) is bisected
/// up to three times at the inside chord midpoint nearest to its middle; those nodes
/// absorb no vertices.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace trimlab {

/// The resampled curve: the input's nodes first (same indices), then the new ones; edges
/// sorted, first < second, without duplicates. A slice without chord midpoints, or whose centre is outside,
/// gets the point of the edge at its parameter if that is inside, else the inside chord
/// midpoint of the slice nearest to it, else the inside chord midpoint of the whole mesh
/// nearest to it (nearestInsideMidpoint). `midpoints`
/// as inwardChordMidpoints(mesh, inside). Throws std::invalid_argument when vertexNode,
/// the mesh and midpoints disagree in size, or spacing is not positive.
[[nodiscard]] CurveSkeleton resampleSkeleton(const CurveSkeleton& curve, const TriangleMesh& mesh,
                                             const std::vector<std::optional<glm::dvec3>>& midpoints,
                                             const PointInMesh& inside, double spacing);

/// Bisects every edge of `curve` that leaves the solid, up to three times, at the inside
/// chord midpoint nearest to the edge's middle (the last step of resampleSkeleton, also
/// run after the nodes moved: centring can swing an edge across a bend). The new nodes
/// absorb no vertices. Returns how many were added; edges stay sorted.
std::size_t splitEdgesLeaving(CurveSkeleton& curve, const std::vector<std::optional<glm::dvec3>>& midpoints,
                              const PointInMesh& inside);

} // namespace trimlab
