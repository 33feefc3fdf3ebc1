#include "core/skinning/skinning_gltf_joints.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

Affine3 boneTransform(const SkinningModel& model, std::size_t pose, std::size_t bone)
{
    return model.method == SkinningMethod::Lbs ? model.affine[pose][bone] : toAffine(model.rigid[pose][bone]);
}

std::vector<glm::dvec3> bonePivots(const SkinningModel& model)
{
    std::vector<glm::dvec3> sum(model.boneCount(), glm::dvec3(0.0));
    std::vector<double> weight(model.boneCount(), 0.0);
    for (std::size_t j = 0; j < model.vertexCount(); ++j) {
        const VertexInfluences& in = model.weights.vertices[j];
        for (std::uint32_t i = 0; i < in.count; ++i) {
            sum[in.bones[i]] += in.weights[i] * model.restPositions[j];
            weight[in.bones[i]] += in.weights[i];
        }
    }
    for (std::size_t b = 0; b < sum.size(); ++b)
        sum[b] = weight[b] > 0.0 ? sum[b] / weight[b] : glm::dvec3(0.0);
    return sum;
}

bool isFinite(const Affine3& a)
{
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(a.linear[c][r]))
                return false;
    return std::isfinite(a.translation.x) && std::isfinite(a.translation.y) && std::isfinite(a.translation.z);
}

// The rigid part of each bone's transform: the closest rotation and the translation that
// keeps the bone exact at its pivot (identity for a transform that is not finite).
std::vector<RigidJointPose> rigidStart(const std::vector<Affine3>& bones, const std::vector<glm::dvec3>& pivots)
{
    std::vector<RigidJointPose> joints(bones.size());
    for (std::size_t b = 0; b < bones.size(); ++b) {
        if (!isFinite(bones[b]))
            continue;
        const glm::dmat3 r = closestRotation(bones[b].linear);
        joints[b].rotation = glm::normalize(glm::quat_cast(r));
        joints[b].translation = bones[b].apply(pivots[b]) - r * pivots[b];
    }
    return joints;
}

void requireTarget(const SkinningModel& model, const std::vector<PosePositions>& target)
{
    if (target.size() != model.poseCount())
        throw std::invalid_argument("rigid joints: " + std::to_string(target.size()) + " target poses for a model of " +
                                    std::to_string(model.poseCount()));
    for (std::size_t t = 0; t < target.size(); ++t)
        if (target[t].size() != model.vertexCount())
            throw std::invalid_argument("rigid joints: target pose " + std::to_string(t) + " has " +
                                        std::to_string(target[t].size()) + " vertices, the model " +
                                        std::to_string(model.vertexCount()));
}

} // namespace

std::vector<std::vector<Affine3>> boneRestToPose(const SkinningModel& model)
{
    std::vector<std::vector<Affine3>> result(model.poseCount(), std::vector<Affine3>(model.boneCount()));
    for (std::size_t t : chainOrder(model.poseCount(), model.restPose)) {
        if (t == model.restPose)
            continue;
        for (std::size_t b = 0; b < model.boneCount(); ++b)
            result[t][b] = compose(boneTransform(model, t, b), result[model.previousPose(t)][b]);
    }
    if (restPoseMoves(model)) // rest-to-pose: no other pose composes the rest pose's own transforms
        result[model.restPose] = model.affine[model.restPose];
    return result;
}

RigidJointAnimation rigidJointAnimation(const SkinningModel& model, const std::vector<PosePositions>& target)
{
    requireTarget(model, target);
    RigidJointAnimation result;
    result.pivots = bonePivots(model);
    const std::vector<std::vector<Affine3>> bones = boneRestToPose(model);
    const RigidJointSolver solver(model.weights, model.restPositions);
    result.poses.resize(model.poseCount());
    for (std::size_t t : chainOrder(model.poseCount(), model.restPose)) {
        std::vector<RigidJointPose> own = rigidStart(bones[t], result.pivots);
        const double ownError = solver.solve(own, target[t]);
        result.poses[t] = std::move(own);
        if (t == model.restPose)
            continue;
        std::vector<RigidJointPose> previous = result.poses[model.previousPose(t)];
        if (solver.solve(previous, target[t]) < ownError || !std::isfinite(ownError))
            result.poses[t] = std::move(previous);
    }
    return result;
}

std::vector<PosePositions> rigidSkinPositions(const std::vector<glm::dvec3>& restPositions,
                                              const SkinningWeights& weights, const RigidJointAnimation& joints)
{
    std::vector<PosePositions> result(joints.poses.size(), PosePositions(restPositions.size()));
    for (std::size_t t = 0; t < joints.poses.size(); ++t) {
        std::vector<glm::dmat3> rotations;
        for (const RigidJointPose& joint : joints.poses[t])
            rotations.push_back(glm::mat3_cast(joint.rotation));
        for (std::size_t j = 0; j < restPositions.size(); ++j) {
            const VertexInfluences& in = weights.vertices[j];
            glm::dvec3 p(0.0);
            double sum = 0.0;
            for (std::uint32_t i = 0; i < in.count; ++i) {
                const std::size_t b = in.bones[i];
                p += in.weights[i] * (rotations[b] * restPositions[j] + joints.poses[t][b].translation);
                sum += in.weights[i];
            }
            result[t][j] = sum > 0.0 ? p / sum : restPositions[j];
        }
    }
    return result;
}

} // namespace trimlab
