#include "core/skeleton/skeleton_refinement.h"

#include <stdexcept>
#include <vector>

namespace trimlab {

std::size_t refineSkeleton(CurveSkeleton& curve, std::span<const glm::dvec3> originalPositions,
                           const PointInMesh& inside)
{
    if (curve.vertexNode.size() != originalPositions.size())
        throw std::invalid_argument("refineSkeleton: vertexNode has " + std::to_string(curve.vertexNode.size()) +
                                    " entries for " + std::to_string(originalPositions.size()) + " vertices");
    std::vector<glm::dvec3> sum(curve.nodes.size(), glm::dvec3(0.0));
    std::vector<std::size_t> count(curve.nodes.size(), 0);
    for (std::size_t v = 0; v < originalPositions.size(); ++v) {
        const int k = curve.vertexNode[v];
        if (k < 0 || static_cast<std::size_t>(k) >= curve.nodes.size())
            throw std::invalid_argument("refineSkeleton: vertex " + std::to_string(v) + " maps to node " +
                                        std::to_string(k) + " of " + std::to_string(curve.nodes.size()));
        sum[static_cast<std::size_t>(k)] += originalPositions[v];
        ++count[static_cast<std::size_t>(k)];
    }
    std::size_t moved = 0;
    for (std::size_t k = 0; k < curve.nodes.size(); ++k) {
        if (count[k] == 0)
            continue;
        // v_k + d_k of eq. (11) is the centroid of Π_k.
        const glm::dvec3 centroid = sum[k] / static_cast<double>(count[k]);
        if (inside.contains(centroid)) {
            curve.nodes[k] = centroid;
            ++moved;
        }
    }
    return moved;
}

} // namespace trimlab
