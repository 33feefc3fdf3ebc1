#pragma once
/// \file
/// Whether a SkeletonRig (skeleton.h) is consistent: a tree of joints rooted at `root`,
/// one bone per non-root joint from its parent to it, bones parents first. Posing, the
/// glTF export and the skeleton JSON loader all rely on these invariants; the extraction
/// produces them, hand-built or loaded rigs are checked here.

#include "core/skeleton/skeleton.h"

#include <cstddef>
#include <optional>
#include <string>

namespace trimlab {

/// The first thing wrong with a rig. `where` names the element in the terms of the
/// skeleton JSON file (skeleton_json.h), so a loader can report it as a JSON path:
/// "nodes[4]", "parent[7]", "root", "bones", "bones[3].head", "bones[3].parent_bone",
/// "vertex_joint[120]" (rig.joints is the file's "nodes").
struct RigProblem {
    std::string where;
    std::string reason;
};

/// Checks, in this order: at least one joint and all of them finite; parent has one entry
/// per joint; root in range with parent −1, every other parent an existing other joint;
/// every joint reaches the root (no cycle); exactly #J − 1 bones; per bone: head and tail
/// in range, head = parent[tail], no tail used twice, parentBone −1 exactly when head is
/// the root and otherwise an EARLIER bone whose tail is the head; every vertexJoint entry
/// names a joint. `vertexCount`, when given, must equal vertexJoint's size unless
/// vertexJoint is empty. nullopt when the rig is consistent. O(#J + #V).
[[nodiscard]] std::optional<RigProblem> findRigProblem(const SkeletonRig& rig,
                                                       std::optional<std::size_t> vertexCount = std::nullopt);

/// Throws std::invalid_argument "<context>: <where>: <reason>" for the first problem.
void requireValidRig(const SkeletonRig& rig, const std::string& context,
                     std::optional<std::size_t> vertexCount = std::nullopt);

} // namespace trimlab
