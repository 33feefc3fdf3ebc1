#include "core/skeleton/rig_validation.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace trimlab {

namespace {

std::string at(const char* field, std::size_t index)
{
    return std::string(field) + "[" + std::to_string(index) + "]";
}

std::string bonePath(std::size_t bone, const char* field)
{
    return at("bones", bone) + "." + field;
}

std::optional<RigProblem> jointProblem(const SkeletonRig& rig)
{
    const std::size_t n = rig.joints.size();
    if (n == 0)
        return RigProblem{"nodes", "the skeleton has no joints"};
    for (std::size_t j = 0; j < n; ++j) {
        const glm::dvec3& p = rig.joints[j];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return RigProblem{at("nodes", j), "joint position is not finite"};
    }
    if (rig.parent.size() != n)
        return RigProblem{"parent",
                          std::to_string(rig.parent.size()) + " entries for " + std::to_string(n) + " joints"};
    if (rig.root < 0 || std::size_t(rig.root) >= n)
        return RigProblem{"root",
                          "joint " + std::to_string(rig.root) + " does not exist (" + std::to_string(n) + " joints)"};
    for (std::size_t j = 0; j < n; ++j) {
        const int p = rig.parent[j];
        if (int(j) == rig.root && p != -1)
            return RigProblem{at("parent", j), "the root joint must have parent -1, not " + std::to_string(p)};
        if (int(j) != rig.root && (p < 0 || std::size_t(p) >= n || p == int(j)))
            return RigProblem{at("parent", j), "parent " + std::to_string(p) + " is not another joint of the " +
                                                   std::to_string(n) + " (only the root has none)"};
    }
    return std::nullopt;
}

// Every joint must reach the root; a parent chain longer than #J is a cycle.
std::optional<RigProblem> treeProblem(const SkeletonRig& rig)
{
    const std::size_t n = rig.joints.size();
    std::vector<std::uint8_t> reaches(n, 0); // 1: known to reach the root
    reaches[std::size_t(rig.root)] = 1;
    std::vector<std::size_t> chain;
    for (std::size_t j = 0; j < n; ++j) {
        chain.clear();
        std::size_t k = j;
        while (!reaches[k]) {
            chain.push_back(k);
            if (chain.size() > n)
                return RigProblem{at("parent", j), "joint " + std::to_string(j) +
                                                       " is on a cycle of parents that never reaches the root"};
            k = std::size_t(rig.parent[k]);
        }
        for (const std::size_t c : chain)
            reaches[c] = 1;
    }
    return std::nullopt;
}

std::optional<RigProblem> boneProblem(const SkeletonRig& rig)
{
    const std::size_t n = rig.joints.size();
    if (rig.bones.size() + 1 != n)
        return RigProblem{"bones", std::to_string(rig.bones.size()) + " bones for " + std::to_string(n) +
                                       " joints (one per non-root joint: " + std::to_string(n - 1) + ")"};
    std::vector<int> boneOfTail(n, -1);
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const Bone& bone = rig.bones[b];
        if (bone.tail < 0 || std::size_t(bone.tail) >= n || bone.tail == rig.root)
            return RigProblem{bonePath(b, "tail"), "joint " + std::to_string(bone.tail) + " is not a non-root joint"};
        if (bone.head != rig.parent[std::size_t(bone.tail)])
            return RigProblem{bonePath(b, "head"), "joint " + std::to_string(bone.head) +
                                                       " is not the parent of tail " + std::to_string(bone.tail)};
        if (boneOfTail[std::size_t(bone.tail)] >= 0)
            return RigProblem{bonePath(b, "tail"), "joint " + std::to_string(bone.tail) +
                                                       " is already the tail of bone " +
                                                       std::to_string(boneOfTail[std::size_t(bone.tail)])};
        boneOfTail[std::size_t(bone.tail)] = int(b);
        const int expected = bone.head == rig.root ? -1 : boneOfTail[std::size_t(bone.head)];
        if (bone.parentBone != expected)
            return RigProblem{bonePath(b, "parent_bone"),
                              expected >= 0 || bone.head == rig.root
                                  ? "is " + std::to_string(bone.parentBone) + ", expected " + std::to_string(expected) +
                                        " (the bone whose tail is the head, or -1 at the root)"
                                  : "the bone ending at joint " + std::to_string(bone.head) +
                                        " must come before this one (bones are ordered parents first)"};
    }
    return std::nullopt;
}

std::optional<RigProblem> vertexProblem(const SkeletonRig& rig, std::optional<std::size_t> vertexCount)
{
    if (vertexCount && !rig.vertexJoint.empty() && rig.vertexJoint.size() != *vertexCount)
        return RigProblem{"vertex_joint", std::to_string(rig.vertexJoint.size()) + " entries for a mesh of " +
                                              std::to_string(*vertexCount) + " vertices"};
    for (std::size_t v = 0; v < rig.vertexJoint.size(); ++v)
        if (rig.vertexJoint[v] < 0 || std::size_t(rig.vertexJoint[v]) >= rig.joints.size())
            return RigProblem{at("vertex_joint", v), "joint " + std::to_string(rig.vertexJoint[v]) + " does not exist"};
    return std::nullopt;
}

} // namespace

std::optional<RigProblem> findRigProblem(const SkeletonRig& rig, std::optional<std::size_t> vertexCount)
{
    if (auto problem = jointProblem(rig))
        return problem;
    if (auto problem = treeProblem(rig))
        return problem;
    if (auto problem = boneProblem(rig))
        return problem;
    return vertexProblem(rig, vertexCount);
}

void requireValidRig(const SkeletonRig& rig, const std::string& context, std::optional<std::size_t> vertexCount)
{
    if (const std::optional<RigProblem> problem = findRigProblem(rig, vertexCount))
        throw std::invalid_argument(context + ": " + problem->where + ": " + problem->reason);
}

} // namespace trimlab
