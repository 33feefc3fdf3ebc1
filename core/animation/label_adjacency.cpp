#include "core/animation/label_adjacency.h"

#include <algorithm>

namespace trimlab {

std::vector<std::vector<std::uint32_t>> labelAdjacency(const VertexGraph& graph, const VertexLabeling& labeling)
{
    std::vector<std::uint64_t> pairs;
    for (std::size_t v = 0; v < graph.vertexCount(); ++v) {
        const std::uint32_t a = labeling.labels[v];
        for (const std::uint32_t n : graph.neighborsOf(v)) {
            const std::uint32_t b = labeling.labels[n];
            if (a != b)
                pairs.push_back((std::uint64_t(a) << 32) | b);
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::vector<std::vector<std::uint32_t>> adjacency(labeling.count);
    for (const std::uint64_t p : pairs)
        adjacency[p >> 32].push_back(std::uint32_t(p));
    return adjacency;
}

} // namespace trimlab
