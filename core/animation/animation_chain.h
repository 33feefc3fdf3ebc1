#pragma once
/// \file
/// A mesh animation as a deformation history for the dynamic rules (thesis 8.1): its
/// poses are the frames. Against the rest pose, every pose is one set whose reference is
/// the rest pose. Against the previous pose, the classification carries from pose to pose
/// (thesis Algorithms 8.11–8.13): from the rest pose to the pose shown, one set per step,
/// each characterized against the one before, so a pose reached by scrubbing shows what
/// playing up to it shows.

#include "core/animation/mesh_animation.h"
#include "core/trim/dynamic_chain.h"

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace trimlab {

enum class PoseReference { Rest, Previous };

/// "rest" / "previous", for the command line and files.
[[nodiscard]] std::string_view poseReferenceName(PoseReference reference);
[[nodiscard]] std::optional<PoseReference> parsePoseReference(std::string_view name);

/// The poses whose positions are the frames of the chain that shows `pose` (see
/// animationChain): {restPose, pose} against the rest pose; against the previous pose,
/// every pose from the rest pose to `pose`, one step at a time (backwards for a pose
/// before the rest pose). Just {restPose} when `pose` is the rest pose.
[[nodiscard]] std::vector<std::size_t> chainPoses(std::size_t restPose, std::size_t pose, PoseReference reference);

/// The chain that shows `pose` of `animation` under `rule` (every set), the rest pose
/// classified by `baseRule`. nullopt when `pose` is the rest pose: nothing has deformed
/// yet, and the base rule alone classifies it. Throws std::out_of_range for a pose that
/// does not exist.
[[nodiscard]] std::optional<DynamicChain> animationChain(const MeshAnimation& animation, std::size_t pose,
                                                         PoseReference reference, DynamicRule rule,
                                                         StaticRule baseRule);

} // namespace trimlab
