#pragma once
/// \file
/// Posing a rig and skinning its mesh (Berenguer & Moreno III.E–F; thesis 2.3.2–2.3.3):
/// each bone turns about its head relative to its parent bone, forward kinematics over
/// the parents-first bone order gives every bone's rigid rest-to-pose motion, and the
/// rest mesh follows by linear blend skinning (LBS, eq. 2.4) or dual quaternion skinning
/// (DQS, eq. 2.5) with the bone-heat weights.
///
/// Conventions: positions are in the rig's (the mesh's) units and frame. A bone's
/// rotation is expressed in rest-pose axes: with every ancestor at rest, rotation q turns
/// the bone and everything below it by q about the bone's head. The motion of bone b is
///
///     W_b = W_parent(b) · T(h_b) · R(q_b) · T(−h_b),      W_parent(root bones) = T(rootTranslation)
///
/// (h_b the rest position of the head), so a child follows its parent (paper III.F: "the
/// transformation applied to a parent bone is inherited by its child").

#include "core/skinning/dual_quaternion.h"
#include "core/skinning/skinning_affine.h"
#include "core/skinning/skinning_model.h"
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/skeleton.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace trimlab {

/// The user-set parameters of a pose.
struct SkeletonPose {
    std::vector<glm::dquat> rotations; ///< #bones, about each bone's head (identity = rest); normalised when used
    glm::dvec3 rootTranslation{0.0};   ///< moves the whole rig
};

/// The rest pose of `rig`: identity rotations, no translation.
[[nodiscard]] SkeletonPose restPose(const SkeletonRig& rig);

/// The motion of every bone (#bones unit dual quaternions, rest → pose) by forward
/// kinematics. Throws std::invalid_argument when the rig is inconsistent
/// (requireValidRig), pose.rotations has the wrong size, or a rotation is zero or not
/// finite (naming the bone), or rootTranslation is not finite.
[[nodiscard]] std::vector<DualQuaternion> boneMotions(const SkeletonRig& rig, const SkeletonPose& pose);

/// The posed joint positions (#J): the root moves with rootTranslation, every other
/// joint with the bone it is the tail of.
[[nodiscard]] std::vector<glm::dvec3> posedJoints(const SkeletonRig& rig, std::span<const DualQuaternion> motions);

/// Skins `rest` (#V) with `weights` (#V, bone indices < motions.size()) and the bone
/// motions: LBS blends the bones' rigid matrices, DQS their dual quaternions (normalised,
/// sign-aligned with the largest weight's; dual_quaternion.h). Writes #V positions to
/// `out` (resized). A vertex without any influence stays where it is. Parallel over
/// blocks of vertices on `threads` threads (0 = all cores). Throws std::invalid_argument
/// when the sizes disagree or a bone index is out of range.
void skinPositions(std::span<const glm::vec3> rest, const BoneWeights& weights, std::span<const DualQuaternion> motions,
                   SkinningMethod method, std::vector<glm::vec3>& out, unsigned threads = 0);

/// Convenience: boneMotions then skinPositions of `rest`.
[[nodiscard]] std::vector<glm::vec3> posePositions(std::span<const glm::vec3> rest, const SkeletonRig& rig,
                                                   const BoneWeights& weights, const SkeletonPose& pose,
                                                   SkinningMethod method, unsigned threads = 0);

} // namespace trimlab
