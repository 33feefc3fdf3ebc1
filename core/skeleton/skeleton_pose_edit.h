#pragma once
/// \file
/// Editing a SkeletonPose (core/skeleton/skeleton_pose.h) the way the Skeleton panel
/// offers it: a bone's rotation as three angles in the bone's local frame, and a drag that
/// turns the posed bone about its posed head around a world axis (the view direction).
///
/// The bone's local frame is the one the glTF export gives its joint (boneOrientation of
/// rigged_gltf.h: +Y along the bone, head → tail, at rest). Angles are glm's Euler angles
/// (pitch about local X, yaw about local Y, roll about local Z, glm::dquat(vec3) and
/// glm::eulerAngles), in degrees. A pose rotation q (rest-pose axes, about the head)
/// relates to the local one by q = O·q_local·O⁻¹ with O the bone's rest orientation.

#include "core/skeleton/skeleton.h"
#include "core/skeleton/skeleton_pose.h"

#include <glm/vec3.hpp>

namespace trimlab {

/// The rotation of `bone` for local Euler angles `degrees` (x, y, z).
[[nodiscard]] glm::dquat boneRotationFromLocalDegrees(const SkeletonRig& rig, int bone, const glm::dvec3& degrees);
/// The local Euler angles (degrees, each in (−180, 180]) of the rotation `rotation` of `bone`.
[[nodiscard]] glm::dvec3 localDegreesOfBoneRotation(const SkeletonRig& rig, int bone, const glm::dquat& rotation);

/// Turns `bone` of `pose` (and everything below it) by `radians` about the world-space
/// (rig-space) `axis` through the bone's posed head: the posed bone moves exactly as a
/// rigid rotation of its current placement. A zero or non-finite axis changes nothing.
/// Throws as boneMotions for an inconsistent rig or pose, std::out_of_range for a bad bone.
void rotateBoneAboutAxis(const SkeletonRig& rig, SkeletonPose& pose, int bone, const glm::dvec3& axis, double radians);

} // namespace trimlab
