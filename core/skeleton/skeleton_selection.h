#pragma once
/// \file
/// Selection (Berenguer & Moreno III.D): reduces the curve skeleton to the 20–40 nodes
/// that serve as animation joints by collapsing its shortest edges (eq. 12:
/// F(i, j) = |v_i − v_j|) and merging the regions of the collapsed nodes.
///
/// What the paper leaves open, decided here:
/// - Spurious branches first. A branch (a chain from a leaf to the nearest node of
///   degree ≥ 3) is an artefact, not an arm, when it is shorter than the local radius at
///   its junction (the mean distance from the junction to the original vertices of its
///   region: it does not stick out of the body there), or when its nodes absorbed fewer
///   than 10 % as many vertices as the junction did (a few vertices left dangling when
///   the triangles around them collapsed, typical where the contraction stopped at a
///   sheet rather than a curve; a real arm absorbs its whole tip and every section along
///   it). Such branches are merged into their junction, repeatedly, before selection.
/// - Nearby junctions next. Two junctions joined by an edge shorter than the sum of their
///   clearances (distance to the nearest mesh vertex: the radius of the ball that fits
///   there) lie in one body: the simplification split one branching point in two. They
///   are merged, shortest first, alternating with the branch pruning until neither
///   changes anything. (This does not catch junctions a few edges apart, as in the
///   two-junction hub of docs/skeleton-extraction.md.)
/// - Arm ends are kept. An edge between a leaf and a junction (degree ≥ 3) is never
///   collapsed, because that would remove the whole arm; the selection stops above the
///   target when only such edges remain. When a leaf is collapsed with its degree-2
///   neighbour the leaf survives, so the arm keeps its tip and only loses an inner node.
/// - Survivor of a collapse: given the solid, the node inside (over one outside), then
///   the leaf, else the node of higher degree (junctions stay at
///   junctions), else the larger region, else the lower index. The survivor keeps its
///   position (inside the mesh wherever the refinement could put it there).
/// - Bones stay inside. Given the solid, a collapse or junction merge whose survivor
///   would gain an edge leaving the solid (a segment that crosses the surface, e.g. the
///   chord of a bent limb once its elbow is collapsed, or a hub joined to an arm across a
///   gap) is skipped, and the next shortest edge is tried; the selection stops above the
///   target when every remaining collapse would leave. Positions never change, so each
///   segment is tested once.

#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace trimlab {

/// Which curve nodes survive selection as joints.
struct NodeSelection {
    std::vector<int> survivors;            ///< #J curve-node indices, ascending (joint j = survivors[j])
    std::vector<int> jointOfNode;          ///< #N: the joint whose region absorbed curve node k
    std::vector<std::array<int, 2>> edges; ///< between joints, first < second, no duplicates
    std::size_t prunedBranches = 0;        ///< spurious branches merged before selection
};

/// Selects at most `targetNodes` joints (fewer only if the curve has fewer nodes; more
/// when only arm-removing collapses remain, see above) from `curve`, whose vertexNode
/// maps the #V vertices at `originalPositions`. Deterministic: the same input gives the
/// same joints in the same order. O(N·E) for N nodes and E edges.
/// `solid` (the mesh, may be null: no containment rule) keeps new bones inside.
/// Throws std::invalid_argument if targetNodes < 1, vertexNode and originalPositions
/// differ in size, or an index is out of range.
[[nodiscard]] NodeSelection selectSkeletonNodes(const CurveSkeleton& curve,
                                                std::span<const glm::dvec3> originalPositions, int targetNodes,
                                                const PointInMesh* solid = nullptr);

} // namespace trimlab
