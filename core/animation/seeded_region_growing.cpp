#include "core/animation/seeded_region_growing.h"

#include <cmath>
#include <limits>
#include <queue>

namespace trimlab {

namespace {

struct Candidate {
    double cost;
    std::uint32_t region;
    std::uint32_t vertex;

    // std::priority_queue pops the largest; "larger" here means taken later.
    bool operator<(const Candidate& other) const
    {
        if (cost != other.cost)
            return cost > other.cost;
        if (region != other.region)
            return region > other.region;
        return vertex > other.vertex;
    }
};

std::vector<double> seedCenters(const FeatureView& feature, std::span<const std::uint32_t> seeds)
{
    std::vector<double> centers;
    for (const std::uint32_t s : seeds)
        for (std::size_t c = 0; c < feature.dimension; ++c)
            centers.push_back(feature.values[s * feature.dimension + c]);
    return centers;
}

// Weighted mean feature of every region (regions × dimension values).
std::vector<double> regionMeans(const FeatureView& feature, std::span<const double> weights,
                                const std::vector<std::uint32_t>& regions, std::size_t count)
{
    const std::size_t d = feature.dimension;
    std::vector<double> sums(count * d, 0.0);
    std::vector<double> mass(count, 0.0);
    for (std::size_t v = 0; v < regions.size(); ++v) {
        if (regions[v] == kNoRegion)
            continue;
        const double w = weights[v] > 0.0 ? weights[v] : 0.0;
        mass[regions[v]] += w;
        for (std::size_t c = 0; c < d; ++c)
            sums[regions[v] * d + c] += w * feature.values[v * d + c];
    }
    for (std::size_t r = 0; r < count; ++r)
        for (std::size_t c = 0; c < d; ++c)
            sums[r * d + c] = mass[r] > 0.0 ? sums[r * d + c] / mass[r] : 0.0;
    return sums;
}

} // namespace

double FeatureView::distance(std::size_t v, std::span<const double> center) const
{
    if (dimension == 1)
        return std::abs(values[v] - center[0]);
    double sum = 0.0;
    for (std::size_t c = 0; c < dimension; ++c) {
        const double d = values[v * dimension + c] - center[c];
        sum += d * d;
    }
    return std::sqrt(sum);
}

std::vector<std::uint32_t> growRegions(const VertexGraph& graph, const FeatureView& feature,
                                       std::span<const std::uint32_t> seeds, std::span<const double> centers,
                                       const GrowthDomain& domain)
{
    std::vector<std::uint32_t> regions(graph.vertexCount(), kNoRegion);
    std::priority_queue<Candidate> queue;
    for (std::size_t r = 0; r < seeds.size(); ++r)
        queue.push({0.0, std::uint32_t(r), seeds[r]});
    while (!queue.empty()) {
        const Candidate next = queue.top();
        queue.pop();
        if (regions[next.vertex] != kNoRegion)
            continue;
        regions[next.vertex] = next.region;
        const std::span<const double> center = centers.subspan(next.region * feature.dimension, feature.dimension);
        for (const std::uint32_t n : graph.neighborsOf(next.vertex)) {
            if (regions[n] == kNoRegion && domain.contains(n))
                queue.push({feature.distance(n, center), next.region, n});
        }
    }
    return regions;
}

std::vector<std::uint32_t> refineRegions(const VertexGraph& graph, const FeatureView& feature,
                                         std::span<const double> weights, std::vector<std::uint32_t>& seeds,
                                         int iterations, const GrowthDomain& domain)
{
    std::vector<std::uint32_t> regions = growRegions(graph, feature, seeds, seedCenters(feature, seeds), domain);
    for (int iteration = 0; iteration < iterations; ++iteration) {
        const std::vector<double> means = regionMeans(feature, weights, regions, seeds.size());
        std::vector<double> best(seeds.size(), std::numeric_limits<double>::infinity());
        std::vector<std::uint32_t> moved = seeds;
        for (std::size_t v = 0; v < regions.size(); ++v) {
            const std::uint32_t r = regions[v];
            if (r == kNoRegion)
                continue;
            const double d =
                feature.distance(v, std::span<const double>(means).subspan(r * feature.dimension, feature.dimension));
            if (d < best[r]) { // strict: the smallest index wins ties
                best[r] = d;
                moved[r] = std::uint32_t(v);
            }
        }
        if (moved == seeds)
            break;
        seeds = moved;
        regions = growRegions(graph, feature, seeds, means, domain);
    }
    return regions;
}

} // namespace trimlab
