#pragma once
/// \file
/// Refinement of the curve skeleton (Berenguer & Moreno III.C): each node moves to the
/// centre of the part of the surface it absorbed (its region Π_k, eq. 11).
///
/// The paper moves a node to the centroid of its region's ORIGINAL positions when that
/// centroid is inside the mesh (Au et al. move unconditionally). The centroid is the
/// centre of a section only when the region samples the whole section evenly: half a
/// ring of a bent limb, a flank absorbed by a junction or a region sampled densely on
/// one side puts it off the axis or outside, and a node left at its contracted position
/// may lie outside. Here every region vertex also votes with the midpoint of its inward
/// chord — from the vertex along its inward normal to the first surface crossing — which
/// lies on the medial axis of a tube whatever part of the ring the vertex is on. A node
/// moves to the first of these that is inside:
///   1. the mean of its region's chord midpoints (the centre of the section);
///   2. the centroid of its region (eq. 11);
///   3. the chord midpoint of its region nearest to (1);
///   4. the inside chord midpoint of the whole mesh nearest to its position (a node the
///      simplification left outside, e.g. between two limbs, whose own region offers no
///      inside point).
/// A node with an empty region that is outside goes to (4) too.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace trimlab {

/// Per vertex of `mesh`: the midpoint of its inward chord (see above), or none where the
/// vertex has no normal or its inward ray finds no surface (an open or inverted part).
/// `inside` must be built from the same mesh. Parallel over vertices.
[[nodiscard]] std::vector<std::optional<glm::dvec3>> inwardChordMidpoints(const TriangleMesh& mesh,
                                                                          const PointInMesh& inside);

/// The inside one of `midpoints` nearest to `p` (the nearest few are tried in order of
/// distance); none when no midpoint is inside. O(#V).
[[nodiscard]] std::optional<glm::dvec3> nearestInsideMidpoint(const glm::dvec3& p,
                                                              const std::vector<std::optional<glm::dvec3>>& midpoints,
                                                              const PointInMesh& inside);

/// Moves the nodes of `curve` in place as described above; `mesh` is the input mesh (its
/// positions are the regions' original positions), `inside` tests against it and
/// `midpoints` are inwardChordMidpoints(mesh, inside). Returns the number of nodes moved.
/// Throws std::invalid_argument if vertexNode, midpoints and the mesh's vertices differ in
/// number or a vertexNode entry is out of range.
std::size_t refineSkeleton(CurveSkeleton& curve, const TriangleMesh& mesh,
                           const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& inside);

} // namespace trimlab
