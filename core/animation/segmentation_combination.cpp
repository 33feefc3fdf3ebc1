#include "core/animation/segmentation_combination.h"

#include "core/animation/p2p_cleaning.h"
#include "core/animation/pose_join.h"

#include <stdexcept>

namespace trimlab {

VertexLabeling combineSegmentations(std::shared_ptr<const VertexGraph> graph, std::span<const double> areas,
                                    std::span<const VertexLabeling> segmentations, double h)
{
    PoseJoin join(std::move(graph));
    for (const VertexLabeling& segmentation : segmentations)
        join.append(segmentation);
    return P2pCleaner(join, areas).clean(h);
}

VertexLabeling transferLabeling(const VertexLabeling& labelingOfB, std::span<const std::uint32_t> bijection)
{
    const std::size_t count = labelingOfB.labels.size();
    if (bijection.size() != count)
        throw std::invalid_argument("transferLabeling: the bijection has " + std::to_string(bijection.size()) +
                                    " entries for " + std::to_string(count) + " vertices");
    std::vector<char> hit(count, 0);
    std::vector<std::uint32_t> labels(count);
    for (std::size_t v = 0; v < count; ++v) {
        if (bijection[v] >= count || hit[bijection[v]]++)
            throw std::invalid_argument("transferLabeling: the vertex map is not a bijection (entry " +
                                        std::to_string(v) + ")");
        labels[v] = labelingOfB.labels[bijection[v]];
    }
    return canonicalLabeling(labels);
}

PoseFeature meanFeature(std::span<const PoseFeature> features)
{
    if (features.empty())
        throw std::invalid_argument("meanFeature: no features");
    PoseFeature mean;
    mean.dimension = features.front().dimension;
    mean.values.assign(features.front().values.size(), 0.0);
    for (const PoseFeature& f : features) {
        if (f.dimension != mean.dimension || f.values.size() != mean.values.size())
            throw std::invalid_argument("meanFeature: the features have different sizes");
        for (std::size_t i = 0; i < f.values.size(); ++i)
            mean.values[i] += f.values[i];
    }
    for (double& v : mean.values)
        v /= double(features.size());
    return mean;
}

VertexLabeling globalSegmentation(const VertexGraph& graph, std::span<const PoseFeature> features,
                                  std::span<const double> areas, const PartitionSettings& settings)
{
    return partitionPose(graph, meanFeature(features), areas, settings);
}

} // namespace trimlab
