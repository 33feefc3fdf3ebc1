#include "core/animation/over_segmentation.h"

#include <stdexcept>

namespace trimlab {

namespace {

// Labels the classes of the transitive closure of "adjacent and same(u, v)".
template <class Same>
VertexLabeling equalNeighbourClasses(const VertexGraph& graph, const Same& same)
{
    constexpr std::uint32_t kNone = UINT32_MAX;
    VertexLabeling result;
    result.labels.assign(graph.vertexCount(), kNone);
    std::vector<std::uint32_t> queue;
    for (std::size_t start = 0; start < graph.vertexCount(); ++start) {
        if (result.labels[start] != kNone)
            continue;
        const std::uint32_t segment = result.count++;
        result.labels[start] = segment;
        queue.assign(1, std::uint32_t(start));
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::uint32_t v = queue[head];
            for (const std::uint32_t n : graph.neighborsOf(v)) {
                if (result.labels[n] == kNone && same(v, n)) {
                    result.labels[n] = segment;
                    queue.push_back(n);
                }
            }
        }
    }
    return result;
}

void requireSize(const VertexLabeling& labeling, std::size_t vertexCount)
{
    if (labeling.labels.size() != vertexCount)
        throw std::invalid_argument("over-segmentation: a labeling has " + std::to_string(labeling.labels.size()) +
                                    " labels for " + std::to_string(vertexCount) + " vertices");
}

} // namespace

VertexLabeling overSegmentation(const VertexGraph& graph, std::span<const VertexLabeling> partitions)
{
    for (const VertexLabeling& p : partitions)
        requireSize(p, graph.vertexCount());
    return equalNeighbourClasses(graph, [&](std::uint32_t u, std::uint32_t v) {
        for (const VertexLabeling& p : partitions) {
            if (p.labels[u] != p.labels[v])
                return false;
        }
        return true;
    });
}

VertexLabeling joinLabelings(const VertexGraph& graph, const VertexLabeling& a, const VertexLabeling& b)
{
    requireSize(a, graph.vertexCount());
    requireSize(b, graph.vertexCount());
    return equalNeighbourClasses(graph, [&](std::uint32_t u, std::uint32_t v) {
        return a.labels[u] == a.labels[v] && b.labels[u] == b.labels[v];
    });
}

} // namespace trimlab
