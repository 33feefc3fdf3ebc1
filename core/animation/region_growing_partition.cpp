#include "core/animation/region_growing_partition.h"

#include <algorithm>

namespace trimlab {

namespace {

constexpr std::uint32_t kUnreached = UINT32_MAX;

// Lowers `distance` to the hop distance from `source` where that is smaller.
void relaxFrom(const VertexGraph& graph, std::uint32_t source, std::vector<std::uint32_t>& distance)
{
    std::vector<std::uint32_t> queue{source};
    distance[source] = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t v = queue[head];
        for (const std::uint32_t n : graph.neighborsOf(v)) {
            if (distance[n] > distance[v] + 1) {
                distance[n] = distance[v] + 1;
                queue.push_back(n);
            }
        }
    }
}

std::uint32_t farthest(const std::vector<std::uint32_t>& distance)
{
    return std::uint32_t(std::max_element(distance.begin(), distance.end()) - distance.begin()); // first maximum
}

} // namespace

std::vector<std::uint32_t> uniformSeeds(const VertexGraph& graph, std::size_t count)
{
    std::vector<std::uint32_t> seeds;
    if (graph.vertexCount() == 0 || count == 0)
        return seeds;
    std::vector<std::uint32_t> distance(graph.vertexCount(), kUnreached);
    relaxFrom(graph, 0, distance);
    const std::uint32_t first = farthest(distance);
    std::fill(distance.begin(), distance.end(), kUnreached);
    seeds.push_back(first);
    relaxFrom(graph, first, distance);
    while (seeds.size() < count) {
        const std::uint32_t next = farthest(distance);
        if (distance[next] == 0)
            break; // every vertex is a seed
        seeds.push_back(next);
        relaxFrom(graph, next, distance);
    }
    return seeds;
}

void labelUnreached(const VertexGraph& graph, std::vector<std::uint32_t>& regions, std::uint32_t next)
{
    std::vector<std::uint32_t> queue;
    for (std::size_t start = 0; start < regions.size(); ++start) {
        if (regions[start] != kNoRegion)
            continue;
        regions[start] = next;
        queue.assign(1, std::uint32_t(start));
        for (std::size_t head = 0; head < queue.size(); ++head) {
            for (const std::uint32_t n : graph.neighborsOf(queue[head])) {
                if (regions[n] == kNoRegion) {
                    regions[n] = next;
                    queue.push_back(n);
                }
            }
        }
        ++next;
    }
}

VertexLabeling regionGrowingPartition(const VertexGraph& graph, const FeatureView& feature,
                                      std::span<const double> weights, std::size_t clusters, int iterations)
{
    std::vector<std::uint32_t> seeds = uniformSeeds(graph, std::max<std::size_t>(clusters, 1));
    std::vector<std::uint32_t> regions = refineRegions(graph, feature, weights, seeds, iterations);
    labelUnreached(graph, regions, std::uint32_t(seeds.size()));
    return canonicalLabeling(regions);
}

} // namespace trimlab
