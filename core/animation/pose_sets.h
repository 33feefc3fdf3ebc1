#pragma once
/// \file
/// An animation's poses grouped into sets of consecutive poses, each with its own dynamic
/// rule (thesis 8.1.1, applied to an animation as in 8.1): set i covers the poses from its
/// first pose up to the pose before the next set's first (the last set: to the last pose),
/// and its reference frame is the pose before its first — the last pose of the set before
/// it, or the rest pose for the first set. The two references of animation_chain.h are the
/// extremes: against the rest pose the whole animation is one set; against the previous
/// pose every pose is a set of its own. Sets cover the poses after the rest pose.

#include "core/animation/animation_chain.h"
#include "core/animation/mesh_animation.h"
#include "core/trim/dynamic_chain.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

struct PoseSet {
    std::size_t firstPose = 1;
    DynamicRule rule = DynamicRule::Confluent;
};

/// "A:rule[,B:rule...]", e.g. "1:confluent,40:additive" (rules by dynamicRuleName).
/// nullopt with the reason in `error` for a malformed item or an unknown rule.
[[nodiscard]] std::optional<std::vector<PoseSet>> parsePoseSets(std::string_view text, std::string& error);
/// The same as text, e.g. "1:confluent,40:additive".
[[nodiscard]] std::string poseSetsText(const std::vector<PoseSet>& sets);

/// Throws std::invalid_argument naming the problem (and what to write instead) unless the
/// sets are not empty, start right after the rest pose, have increasing first poses and
/// lie within the animation's poses.
void requireValidPoseSets(const std::vector<PoseSet>& sets, std::size_t restPose, std::size_t poseCount);

/// The index of the set that holds `pose` (> restPose); sets as requireValidPoseSets wants.
[[nodiscard]] std::size_t setOfPose(const std::vector<PoseSet>& sets, std::size_t pose);

/// The sets `reference` makes of the poses after `restPose` under `rule`: one set from
/// restPose + 1 (rest), or one per pose (previous). Empty when the rest pose is the last.
[[nodiscard]] std::vector<PoseSet> referenceSets(std::size_t restPose, std::size_t poseCount, PoseReference reference,
                                                 DynamicRule rule);

/// The last level of poseSetChain's chain for `pose` (> restPose; sets as
/// requireValidPoseSets wants): the pose against its set's reference, under its set's
/// rule. What a renderer that keeps the earlier levels needs for the next pose.
[[nodiscard]] DynamicChainLevel poseSetShownLevel(const MeshAnimation& animation, std::size_t pose,
                                                  const std::vector<PoseSet>& sets);

/// The chain that shows `pose`: frames the rest pose, the reference of every set up to
/// the pose's, and the pose; each level with its set's rule; the rest pose classified by
/// `baseRule`. nullopt for the rest pose. Throws std::invalid_argument for invalid sets or
/// a pose before the rest pose, std::out_of_range for a pose that does not exist.
[[nodiscard]] std::optional<DynamicChain> poseSetChain(const MeshAnimation& animation, std::size_t pose,
                                                       const std::vector<PoseSet>& sets, StaticRule baseRule);

} // namespace trimlab
