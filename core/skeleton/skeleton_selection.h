#pragma once
/// \file
/// Selection (Berenguer & Moreno III.D): reduces the curve skeleton to the 20–40 nodes
/// that serve as animation joints, merging the regions of the nodes that are not joints
/// into the joints beside them.
///
/// The paper collapses the shortest edges (eq. 12: F(i, j) = |v_i − v_j|). On real
/// characters that spends the joints on fingers and toes, whose edges are short but
/// whose tips must stay, and merges the spine's junctions into one hub. Here the joints
/// follow the body instead:
/// - Spurious branches first. A branch (a chain from a leaf to the nearest node of
///   degree ≥ 3) is an artefact, not an arm, when it is shorter than the local radius at
///   its junction (the mean distance from the junction to the original vertices of its
///   region: it does not stick out of the body there), or when its nodes absorbed fewer
///   than 10 % as many vertices as the junction did. Such branches are merged into their
///   junction, repeatedly.
/// - Nearby junctions next. Two junctions joined by an edge shorter than the sum of their
///   clearances (distance to the nearest mesh vertex) lie in one body and are merged,
///   shortest first, alternating with the branch pruning until neither changes anything.
/// - Limbs below the resolution. A limb (leaf to junction) shorter than the joint spacing
///   (the alive curve's length over the target) is merged into its junction, the
///   shortest first and with its siblings below the spacing, so that a hand whose fingers
///   all go ends its arm; also while there are more leaves and junctions than the target.
/// - The root: body_root.h on the curve at this point, where every limb still carries
///   all of its vertices.
/// - Joints on the chains. Every junction and leaf is a joint. The chains between them
///   gain joints one at a time: first a segment that must be split (its chord leaves the
///   solid, it closes a loop on one joint, or it doubles another segment's pair of
///   joints), then the longest segment while the count is below the target. A segment
///   that bends (a node farther than 10 % of its chord from it) or must be split gains
///   the node farthest from its chord; a straight one the narrowest node of its middle
///   half (a knee held straight narrows). Nodes where the new joint would make a bone turn
///   back on its neighbour along the chain by more than 120° are passed over.
/// - Turn-backs straightened, from the root: a bone that turns back on its parent by
///   more than 120° loses the joint between them when the two form a fold, or is hung
///   from the nearest joint up the tree that holds it inside without turning back.
/// - Positions never change (each segment is tested against the solid once).

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
    std::size_t prunedBranches = 0;        ///< spurious and below-resolution branches merged
    /// The joint at the body's root (body_root.h), found on the curve before the joints
    /// were placed, where every limb still carries all of its vertices; −1 when unknown.
    int root = -1;
};

/// Selects about `targetNodes` joints from `curve` (fewer when the curve has fewer nodes
/// or folds were straightened; more when chords must be split to stay inside), whose
/// vertexNode maps the #V vertices at `originalPositions`. Deterministic: the same input
/// gives the same joints in the same order. O(N·(N + E)) for N nodes and E edges.
/// `solid` (the mesh, may be null: no containment rule) keeps new bones inside.
/// Throws std::invalid_argument if targetNodes < 1, vertexNode and originalPositions
/// differ in size, or an index is out of range.
[[nodiscard]] NodeSelection selectSkeletonNodes(const CurveSkeleton& curve,
                                                std::span<const glm::dvec3> originalPositions, int targetNodes,
                                                const PointInMesh* solid = nullptr);

} // namespace trimlab
