#include "core/skeleton/rig_measures.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace trimlab {

namespace {

constexpr double kLeakingShare = 0.25;

// The angle between a bone's direction and its parent bone's, in degrees.
double turnDegrees(const SkeletonRig& rig, const Bone& bone)
{
    const Bone& parent = rig.bones[static_cast<std::size_t>(bone.parentBone)];
    const glm::dvec3 in =
        rig.joints[static_cast<std::size_t>(parent.tail)] - rig.joints[static_cast<std::size_t>(parent.head)];
    const glm::dvec3 out =
        rig.joints[static_cast<std::size_t>(bone.tail)] - rig.joints[static_cast<std::size_t>(bone.head)];
    const double lengths = glm::length(in) * glm::length(out);
    if (lengths == 0.0)
        return 0.0;
    return std::acos(std::clamp(glm::dot(in, out) / lengths, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// Per joint, whether each bone ends at that joint or at one of its tree neighbours.
std::vector<std::vector<char>> bonesAroundJoints(const SkeletonRig& rig)
{
    const std::size_t jointCount = rig.joints.size();
    std::vector<std::vector<int>> neighbours(jointCount);
    for (const Bone& bone : rig.bones) {
        neighbours[static_cast<std::size_t>(bone.head)].push_back(bone.tail);
        neighbours[static_cast<std::size_t>(bone.tail)].push_back(bone.head);
    }
    std::vector<std::vector<char>> around(jointCount, std::vector<char>(rig.bones.size(), 0));
    for (std::size_t j = 0; j < jointCount; ++j) {
        std::vector<int> near = neighbours[j];
        near.push_back(static_cast<int>(j));
        for (std::size_t b = 0; b < rig.bones.size(); ++b)
            for (int k : near)
                if (rig.bones[b].head == k || rig.bones[b].tail == k)
                    around[j][b] = 1;
    }
    return around;
}

} // namespace

RigMeasures measureRig(const SkeletonRig& rig, const BoneWeights& weights)
{
    if (weights.vertexCount() != rig.vertexJoint.size())
        throw std::invalid_argument("measureRig: " + std::to_string(weights.vertexCount()) + " weighted vertices for " +
                                    std::to_string(rig.vertexJoint.size()) + " vertices of the rig");
    RigMeasures measures;
    measures.joints = static_cast<int>(rig.joints.size());
    for (const Bone& bone : rig.bones) {
        if (bone.head == rig.root)
            ++measures.rootBones;
        if (bone.parentBone < 0)
            continue;
        const double degrees = turnDegrees(rig, bone);
        measures.sharpestTurnDegrees = std::max(measures.sharpestTurnDegrees, degrees);
        if (degrees > kTurnBackDegrees)
            ++measures.turnBacks;
    }

    const std::vector<std::vector<char>> around = bonesAroundJoints(rig);
    double total = 0.0, leaked = 0.0;
    std::size_t leakingVertices = 0, counted = 0;
    for (std::size_t v = 0; v < weights.vertexCount(); ++v) {
        const int joint = rig.vertexJoint[v];
        if (joint < 0)
            continue;
        ++counted;
        double away = 0.0;
        for (std::size_t slot = 0; slot < kBoneInfluences; ++slot) {
            const int bone = weights.bones[v][slot];
            if (bone < 0)
                continue;
            if (static_cast<std::size_t>(bone) >= rig.bones.size())
                throw std::invalid_argument("measureRig: vertex " + std::to_string(v) + " names bone " +
                                            std::to_string(bone) + " of " + std::to_string(rig.bones.size()));
            const double w = weights.weights[v][slot];
            total += w;
            if (!around[static_cast<std::size_t>(joint)][static_cast<std::size_t>(bone)])
                away += w;
        }
        leaked += away;
        if (away > kLeakingShare)
            ++leakingVertices;
    }
    measures.leakedWeight = total > 0.0 ? leaked / total : 0.0;
    measures.leakingVertices = counted > 0 ? static_cast<double>(leakingVertices) / static_cast<double>(counted) : 0.0;
    return measures;
}

std::string describeRigMeasures(const RigMeasures& m)
{
    char line[256];
    std::snprintf(line, sizeof line,
                  "%d joints, %d bones at the root, %d turn-backs beyond %.0f° (sharpest %.0f°), weight leakage "
                  "%.1f %% (%.1f %% of vertices)",
                  m.joints, m.rootBones, m.turnBacks, kTurnBackDegrees, m.sharpestTurnDegrees, 100.0 * m.leakedWeight,
                  100.0 * m.leakingVertices);
    return line;
}

} // namespace trimlab
