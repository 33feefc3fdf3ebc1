#include "core/skeleton/leaf_extension.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

namespace trimlab {

namespace {

// Halvings of an extension that would leave the solid before it is given up.
constexpr int kShrinkSteps = 4;

} // namespace

RegionReach regionReach(const std::vector<std::size_t>& region, const TriangleMesh& mesh, const glm::dvec3& from,
                        const glm::dvec3& direction)
{
    RegionReach reach;
    for (std::size_t v : region) {
        const glm::dvec3 offset = glm::dvec3(mesh.positions[v]) - from;
        const double along = glm::dot(offset, direction);
        reach.ahead = std::max(reach.ahead, along);
        reach.radius += glm::length(offset - along * direction);
    }
    reach.radius /= static_cast<double>(region.size());
    return reach;
}

std::vector<int> leafNeighbours(const CurveSkeleton& curve)
{
    std::vector<int> degree(curve.nodes.size(), 0), neighbour(curve.nodes.size(), -1);
    for (const auto& edge : curve.edges) {
        ++degree[static_cast<std::size_t>(edge[0])];
        ++degree[static_cast<std::size_t>(edge[1])];
        neighbour[static_cast<std::size_t>(edge[0])] = edge[1];
        neighbour[static_cast<std::size_t>(edge[1])] = edge[0];
    }
    for (std::size_t k = 0; k < neighbour.size(); ++k)
        if (degree[k] != 1)
            neighbour[k] = -1;
    return neighbour;
}

std::size_t extendLeaves(CurveSkeleton& curve, const TriangleMesh& mesh, const PointInMesh& solid)
{
    const std::vector<int> neighbour = leafNeighbours(curve);
    std::vector<std::vector<std::size_t>> regions(curve.nodes.size());
    for (std::size_t v = 0; v < curve.vertexNode.size() && v < mesh.vertexCount(); ++v)
        if (const int k = curve.vertexNode[v]; k >= 0 && neighbour[static_cast<std::size_t>(k)] >= 0)
            regions[static_cast<std::size_t>(k)].push_back(v);

    std::size_t moved = 0;
    for (std::size_t k = 0; k < curve.nodes.size(); ++k) {
        if (neighbour[k] < 0 || regions[k].empty())
            continue;
        const glm::dvec3 leaf = curve.nodes[k];
        const glm::dvec3 along = leaf - curve.nodes[static_cast<std::size_t>(neighbour[k])];
        if (glm::length(along) == 0.0)
            continue;
        const glm::dvec3 direction = glm::normalize(along);
        const RegionReach reach = regionReach(regions[k], mesh, leaf, direction);
        double step = reach.ahead - reach.radius;
        for (int attempt = 0; step > 0.0 && attempt <= kShrinkSteps; ++attempt, step *= 0.5) {
            const glm::dvec3 tip = leaf + step * direction;
            if (solid.segmentInside(leaf, tip)) {
                curve.nodes[k] = tip;
                ++moved;
                break;
            }
        }
    }
    return moved;
}

} // namespace trimlab
