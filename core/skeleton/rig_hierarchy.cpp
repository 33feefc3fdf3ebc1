#include "core/skeleton/rig_hierarchy.h"

#include "core/skeleton/body_root.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

using Adjacency = std::vector<std::vector<int>>;

int automaticRoot(const Adjacency& adjacent, const std::vector<int>& vertexJoint)
{
    std::vector<std::size_t> mass(adjacent.size(), 0);
    for (int j : vertexJoint)
        if (j >= 0)
            ++mass[static_cast<std::size_t>(j)];
    return bodyRoot(adjacent, mass);
}

// The unvisited joint nearest to a visited one, and that visited joint.
std::pair<int, int> nearestOutside(const std::vector<glm::dvec3>& joints, const std::vector<char>& visited)
{
    double best = std::numeric_limits<double>::infinity();
    std::pair<int, int> pair{-1, -1};
    for (std::size_t out = 0; out < joints.size(); ++out) {
        if (visited[out])
            continue;
        for (std::size_t in = 0; in < joints.size(); ++in)
            if (visited[in])
                if (const double d = glm::length(joints[out] - joints[in]); d < best) {
                    best = d;
                    pair = {static_cast<int>(out), static_cast<int>(in)};
                }
    }
    return pair;
}

// Parents by breadth-first search from the root; returns the joints in visiting order.
std::vector<int> spanningTree(const std::vector<glm::dvec3>& joints, const Adjacency& adjacent, int root,
                              std::vector<int>& parent)
{
    std::vector<char> visited(joints.size(), 0);
    std::vector<int> order;
    std::deque<int> queue{root};
    visited[static_cast<std::size_t>(root)] = 1;
    while (order.size() < joints.size()) {
        if (queue.empty()) { // another component: attach it where it comes closest
            const auto [out, in] = nearestOutside(joints, visited);
            parent[static_cast<std::size_t>(out)] = in;
            visited[static_cast<std::size_t>(out)] = 1;
            queue.push_back(out);
        }
        const int j = queue.front();
        queue.pop_front();
        order.push_back(j);
        for (int k : adjacent[static_cast<std::size_t>(j)])
            if (!visited[static_cast<std::size_t>(k)]) {
                visited[static_cast<std::size_t>(k)] = 1;
                parent[static_cast<std::size_t>(k)] = j;
                queue.push_back(k);
            }
    }
    return order;
}

} // namespace

SkeletonRig buildSkeletonRig(const CurveSkeleton& curve, const NodeSelection& selection,
                             std::span<const glm::dvec3> originalPositions, int rootJoint)
{
    SkeletonRig rig;
    const std::size_t jointCount = selection.survivors.size();
    if (rootJoint >= 0 && static_cast<std::size_t>(rootJoint) >= jointCount)
        throw std::invalid_argument("root joint " + std::to_string(rootJoint) + " does not exist: the rig has " +
                                    std::to_string(jointCount) + " joints (0 to " +
                                    std::to_string(static_cast<long long>(jointCount) - 1) + ")");
    rig.vertexJoint.assign(originalPositions.size(), -1);
    if (jointCount == 0)
        return rig;
    for (int k : selection.survivors)
        rig.joints.push_back(curve.nodes[static_cast<std::size_t>(k)]);
    Adjacency adjacent(jointCount);
    for (const std::array<int, 2>& e : selection.edges) {
        adjacent[static_cast<std::size_t>(e[0])].push_back(e[1]);
        adjacent[static_cast<std::size_t>(e[1])].push_back(e[0]);
    }
    for (std::vector<int>& around : adjacent)
        std::sort(around.begin(), around.end());
    for (std::size_t v = 0; v < originalPositions.size() && v < curve.vertexNode.size(); ++v)
        if (const int k = curve.vertexNode[v]; k >= 0 && static_cast<std::size_t>(k) < selection.jointOfNode.size())
            rig.vertexJoint[v] = selection.jointOfNode[static_cast<std::size_t>(k)];
    rig.root = rootJoint >= 0        ? rootJoint
               : selection.root >= 0 ? selection.root
                                     : automaticRoot(adjacent, rig.vertexJoint);
    rig.parent.assign(jointCount, -1);
    const std::vector<int> order = spanningTree(rig.joints, adjacent, rig.root, rig.parent);
    std::vector<int> boneOfTail(jointCount, -1);
    for (int j : order) {
        if (j == rig.root)
            continue;
        const int head = rig.parent[static_cast<std::size_t>(j)];
        boneOfTail[static_cast<std::size_t>(j)] = static_cast<int>(rig.bones.size());
        rig.bones.push_back(Bone{head, j, boneOfTail[static_cast<std::size_t>(head)]});
    }
    return rig;
}

} // namespace trimlab
