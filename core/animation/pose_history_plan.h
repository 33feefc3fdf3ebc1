#pragma once
/// \file
/// How a renderer that holds the dynamic-rule chain of one pose of an animation gets to
/// the chain of another (thesis 8.1: the animation as a deformation history, its poses
/// grouped into sets, pose_sets.h). Three steps exist, from cheapest:
/// - ReplaceShown: the wanted pose lies in the same set as the pose shown, so the chains
///   share every reference and only the shown (last) level changes;
/// - Append(levels): the pose shown is the reference of the wanted pose's next set — it
///   ends a set the wanted chain has — so the held chain is the start of the wanted one
///   and only the new levels are characterized (playing forward against the previous
///   pose: one level per pose);
/// - New: anything else (scrubbing back, a jump across the rest pose, no chain held).
/// Both the `trimlab render --poses` verb and the GUI's timeline ask this one pure
/// function, so they take the same step for the same poses; either step renders the same
/// picture as New.

#include "core/animation/animation_chain.h"
#include "core/animation/pose_sets.h"
#include "core/trim/dynamic_rule.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace trimlab {

/// The sets of a history on both sides of the rest pose.
struct PoseHistorySets {
    std::size_t restPose = 0;
    /// The poses after the rest pose, as pose_sets.h describes them: the first set starts
    /// at restPose + 1, first poses increase, set i's reference is its first pose − 1.
    std::vector<PoseSet> after;
    /// The poses before the rest pose, seen backwards from it: the first set starts at
    /// restPose − 1, first poses decrease, set i covers the poses from its first pose down
    /// to the pose above the next set's first, and its reference is its first pose + 1.
    std::vector<PoseSet> before;
};

/// The sets `reference` makes on both sides of the rest pose of an animation of
/// `poseCount` poses under `rule`: one set per side against the rest pose, one set per
/// pose against the previous pose (referenceSets on the side after the rest pose).
[[nodiscard]] PoseHistorySets referenceHistory(std::size_t restPose, std::size_t poseCount, PoseReference reference,
                                               DynamicRule rule);

/// One level of a chain: pose `pose` characterized against pose `reference` by `rule`.
struct PoseHistoryLevel {
    std::size_t reference = 0;
    std::size_t pose = 0;
    DynamicRule rule = DynamicRule::Confluent;

    friend bool operator==(const PoseHistoryLevel&, const PoseHistoryLevel&) = default;
};

struct PoseHistoryStep {
    enum class Kind { New, Append, ReplaceShown };
    Kind kind = Kind::New;
    /// New: every level of the wanted pose's chain, from the rest pose on (none for the
    /// rest pose itself, which the base rule alone classifies); Append: the levels to
    /// append, in order; ReplaceShown: the one new shown level.
    std::vector<PoseHistoryLevel> levels;

    friend bool operator==(const PoseHistoryStep&, const PoseHistoryStep&) = default;
};

/// The levels of the chain that shows `pose`, from the rest pose on; empty for the rest
/// pose. Throws std::invalid_argument for a pose on a side without sets or for sets that
/// do not start next to the rest pose or do not move away from it.
[[nodiscard]] std::vector<PoseHistoryLevel> poseHistoryLevels(const PoseHistorySets& sets, std::size_t pose);

/// The step from the chain of `shown` (nullopt: the renderer holds no chain; the rest pose
/// holds none either) to the chain of `wanted`. Throws as poseHistoryLevels.
[[nodiscard]] PoseHistoryStep planPoseHistory(const PoseHistorySets& sets, std::optional<std::size_t> shown,
                                              std::size_t wanted);

} // namespace trimlab
