#pragma once
/// \file
/// The animation rig of the selected joints (Berenguer & Moreno III.D/F): a tree of
/// joints with one parent each (the root has none) and one bone per non-root joint,
/// parents first — the hierarchy posing and export walk.

#include "core/skeleton/skeleton.h"
#include "core/skeleton/skeleton_selection.h"

#include <glm/vec3.hpp>

#include <span>

namespace trimlab {

/// Builds the rig of `selection` over `curve` (joint j sits at curve.nodes[survivors[j]];
/// joints keep the selection's order, so a joint index names the same joint whatever
/// the root). `originalPositions` (#V) are the mesh's positions.
/// - Root: `rootJoint` when ≥ 0 (throws std::invalid_argument unless < #J); otherwise
///   the selection's root when it has one, else body_root.h on the joints (weighed by
///   the vertices of their regions).
/// - Tree: breadth-first from the root, neighbours in increasing index order. Edges that
///   would close a cycle (one per handle of a genus-g mesh: the skeleton of a torus is a
///   loop) are dropped, so the loop opens opposite the root; a bone cannot have two
///   parents. Joints in other components (not produced by a connected mesh) are attached
///   to the nearest joint already in the tree, nearest pair first.
/// - Bones: one per non-root joint, in breadth-first order (parents first); head =
///   parent joint, tail = joint, parentBone = the bone whose tail is the head, −1 at the
///   root.
/// - vertexJoint (#V): the joint of the region that holds each vertex.
/// An empty selection gives an empty rig (no joints, root 0, vertexJoint all −1).
[[nodiscard]] SkeletonRig buildSkeletonRig(const CurveSkeleton& curve, const NodeSelection& selection,
                                           std::span<const glm::dvec3> originalPositions, int rootJoint);

} // namespace trimlab
