#include "core/skeleton/skeleton_pose_edit.h"

#include "core/skeleton/rigged_gltf.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

const Bone& boneAt(const SkeletonRig& rig, int bone)
{
    if (bone < 0 || std::size_t(bone) >= rig.bones.size())
        throw std::out_of_range("bone " + std::to_string(bone) + " is not one of the rig's " +
                                std::to_string(rig.bones.size()) + " bones");
    return rig.bones[std::size_t(bone)];
}

glm::dquat restOrientation(const SkeletonRig& rig, int bone)
{
    const Bone& b = boneAt(rig, bone);
    return boneOrientation(rig.joints[std::size_t(b.head)], rig.joints[std::size_t(b.tail)]);
}

double wrapDegrees(double degrees)
{
    double d = std::remainder(degrees, 360.0); // [−180, 180]
    if (d <= -180.0)
        d += 360.0;
    return std::abs(d) < 1e-9 ? 0.0 : d;
}

} // namespace

glm::dquat boneRotationFromLocalDegrees(const SkeletonRig& rig, int bone, const glm::dvec3& degrees)
{
    const glm::dquat o = restOrientation(rig, bone);
    const glm::dquat local(glm::radians(degrees));
    return glm::normalize(o * local * glm::inverse(o));
}

glm::dvec3 localDegreesOfBoneRotation(const SkeletonRig& rig, int bone, const glm::dquat& rotation)
{
    const glm::dquat o = restOrientation(rig, bone);
    const glm::dvec3 degrees = glm::degrees(glm::eulerAngles(glm::normalize(glm::inverse(o) * rotation * o)));
    return {wrapDegrees(degrees.x), wrapDegrees(degrees.y), wrapDegrees(degrees.z)};
}

void rotateBoneAboutAxis(const SkeletonRig& rig, SkeletonPose& pose, int bone, const glm::dvec3& axis, double radians)
{
    const Bone& b = boneAt(rig, bone);
    const double length = glm::length(axis);
    if (!std::isfinite(length) || length <= 0.0 || !std::isfinite(radians))
        return;
    // W_b = W_p·T(h)·R(q)·T(−h) and W_p = T(h′)·R_p·T(−h) (h′ the posed head), so turning
    // the posed bone by R(a, θ) about h′ is q ← R_p⁻¹·R(a, θ)·R_p·q = R(R_p⁻¹a, θ)·q.
    glm::dquat parent(1.0, 0.0, 0.0, 0.0);
    if (b.parentBone >= 0)
        parent = glm::normalize(boneMotions(rig, pose)[std::size_t(b.parentBone)].real);
    const glm::dvec3 localAxis = glm::inverse(parent) * (axis / length);
    glm::dquat& q = pose.rotations.at(std::size_t(bone));
    q = glm::normalize(glm::angleAxis(radians, glm::normalize(localAxis)) * glm::normalize(q));
}

} // namespace trimlab
