#include "core/skeleton/skeleton_pose.h"

#include "core/util/parallel_for.h"
#include "core/skeleton/rig_validation.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

bool isFinite(const glm::dquat& q)
{
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

// A block of vertices per parallel work item: large enough that a 50k-vertex drag costs
// a handful of thread hand-offs, small enough to balance two to sixteen cores.
constexpr std::size_t kSkinBlock = 4096;

void requireSkinnable(std::span<const glm::vec3> rest, const BoneWeights& weights, std::size_t boneCount)
{
    if (weights.bones.size() != rest.size() || weights.weights.size() != rest.size())
        throw std::invalid_argument("skinning: " + std::to_string(weights.bones.size()) + " weighted vertices for " +
                                    std::to_string(rest.size()) + " rest positions");
    for (std::size_t v = 0; v < rest.size(); ++v)
        for (std::size_t k = 0; k < kBoneInfluences; ++k)
            if (weights.bones[v][k] >= int(boneCount) || (weights.bones[v][k] < 0 && weights.weights[v][k] != 0.0f))
                throw std::invalid_argument("skinning: vertex " + std::to_string(v) + " names bone " +
                                            std::to_string(weights.bones[v][k]) + " of " + std::to_string(boneCount));
}

glm::vec3 lbsVertex(const glm::vec3& p, const std::array<int, kBoneInfluences>& bones,
                    const std::array<float, kBoneInfluences>& w, std::span<const Affine3> matrices)
{
    Affine3 sum{glm::dmat3(0.0), glm::dvec3(0.0)};
    double total = 0.0;
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (bones[k] >= 0 && w[k] > 0.0f) {
            sum = weightedSum(sum, matrices[std::size_t(bones[k])], double(w[k]));
            total += double(w[k]);
        }
    return total > 0.0 ? glm::vec3(sum.apply(glm::dvec3(p)) / total) : p;
}

glm::vec3 dqsVertex(const glm::vec3& p, const std::array<int, kBoneInfluences>& bones,
                    const std::array<float, kBoneInfluences>& w, std::span<const DualQuaternion> motions)
{
    std::array<DualQuaternion, kBoneInfluences> used;
    std::array<double, kBoneInfluences> weights{};
    std::size_t count = 0;
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (bones[k] >= 0 && w[k] > 0.0f) {
            used[count] = motions[std::size_t(bones[k])];
            weights[count++] = double(w[k]);
        }
    if (count == 0)
        return p;
    // Slots are sorted by decreasing weight: the first is the pivot of the sign alignment.
    const DualQuaternion blend =
        blendDualQuaternions(std::span(used.data(), count), std::span(weights.data(), count), used[0]);
    return glm::vec3(transformPoint(blend, glm::dvec3(p)));
}

} // namespace

SkeletonPose restPose(const SkeletonRig& rig)
{
    SkeletonPose pose;
    pose.rotations.assign(rig.bones.size(), glm::dquat(1.0, 0.0, 0.0, 0.0));
    return pose;
}

std::vector<DualQuaternion> boneMotions(const SkeletonRig& rig, const SkeletonPose& pose)
{
    requireValidRig(rig, "posing");
    if (pose.rotations.size() != rig.bones.size())
        throw std::invalid_argument("posing: " + std::to_string(pose.rotations.size()) + " rotations for " +
                                    std::to_string(rig.bones.size()) + " bones");
    const glm::dvec3& shift = pose.rootTranslation;
    if (!std::isfinite(shift.x) || !std::isfinite(shift.y) || !std::isfinite(shift.z))
        throw std::invalid_argument("posing: the root translation is not finite");
    const DualQuaternion root = dualQuaternionFromRigid(glm::dquat(1.0, 0.0, 0.0, 0.0), shift);
    std::vector<DualQuaternion> motions(rig.bones.size());
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const glm::dquat& q = pose.rotations[b];
        if (!isFinite(q) || !(glm::dot(q, q) > 0.0))
            throw std::invalid_argument("posing: the rotation of bone " + std::to_string(b) + " is zero or not finite");
        const glm::dquat r = glm::normalize(q);
        const glm::dvec3 head = rig.joints[std::size_t(rig.bones[b].head)];
        // x ↦ R(x − h) + h: the rotation about the head.
        const DualQuaternion local = dualQuaternionFromRigid(r, head - r * head);
        const int parent = rig.bones[b].parentBone;
        motions[b] = normalized((parent < 0 ? root : motions[std::size_t(parent)]) * local);
    }
    return motions;
}

std::vector<glm::dvec3> posedJoints(const SkeletonRig& rig, std::span<const DualQuaternion> motions)
{
    if (motions.size() != rig.bones.size())
        throw std::invalid_argument("posing: " + std::to_string(motions.size()) + " motions for " +
                                    std::to_string(rig.bones.size()) + " bones");
    std::vector<glm::dvec3> joints = rig.joints;
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const int tail = rig.bones[b].tail;
        joints[std::size_t(tail)] = transformPoint(motions[b], rig.joints[std::size_t(tail)]);
    }
    // The root moves with the translation every root bone shares; without bones it stays.
    for (std::size_t b = 0; b < rig.bones.size(); ++b)
        if (rig.bones[b].parentBone < 0) {
            joints[std::size_t(rig.root)] = transformPoint(motions[b], rig.joints[std::size_t(rig.root)]);
            break;
        }
    return joints;
}

void skinPositions(std::span<const glm::vec3> rest, const BoneWeights& weights, std::span<const DualQuaternion> motions,
                   SkinningMethod method, std::vector<glm::vec3>& out, unsigned threads)
{
    requireSkinnable(rest, weights, motions.size());
    std::vector<Affine3> matrices;
    if (method == SkinningMethod::Lbs) {
        matrices.reserve(motions.size());
        for (const DualQuaternion& m : motions)
            matrices.push_back(toAffine(m));
    }
    out.resize(rest.size());
    const std::size_t blocks = (rest.size() + kSkinBlock - 1) / kSkinBlock;
    parallelFor(blocks, threads, [&](std::size_t block) {
        const std::size_t end = std::min(rest.size(), (block + 1) * kSkinBlock);
        for (std::size_t v = block * kSkinBlock; v < end; ++v)
            out[v] = method == SkinningMethod::Lbs ? lbsVertex(rest[v], weights.bones[v], weights.weights[v], matrices)
                                                   : dqsVertex(rest[v], weights.bones[v], weights.weights[v], motions);
    });
}

std::vector<glm::vec3> posePositions(std::span<const glm::vec3> rest, const SkeletonRig& rig,
                                     const BoneWeights& weights, const SkeletonPose& pose, SkinningMethod method,
                                     unsigned threads)
{
    std::vector<glm::vec3> out;
    skinPositions(rest, weights, boneMotions(rig, pose), method, out, threads);
    return out;
}

} // namespace trimlab
