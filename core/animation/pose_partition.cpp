#include "core/animation/pose_partition.h"

#include "core/animation/hierarchical_partition.h"
#include "core/animation/region_growing_partition.h"

#include <algorithm>

namespace trimlab {

VertexLabeling partitionPose(const VertexGraph& graph, const PoseFeature& feature, std::span<const double> weights,
                             const PartitionSettings& settings)
{
    const FeatureView view{feature.values, feature.dimension};
    const std::size_t clusters = std::max<std::size_t>(settings.clusters, 1);
    if (settings.method == PartitionMethod::Hierarchical)
        return hierarchicalPartition(graph, view, weights, clusters, settings.iterations);
    return regionGrowingPartition(graph, view, weights, clusters, settings.iterations);
}

std::string_view partitionMethodName(PartitionMethod method)
{
    return method == PartitionMethod::Hierarchical ? "hierarchical" : "region-growing";
}

std::optional<PartitionMethod> parsePartitionMethod(std::string_view name)
{
    if (name == "hierarchical")
        return PartitionMethod::Hierarchical;
    if (name == "region-growing")
        return PartitionMethod::RegionGrowing;
    return std::nullopt;
}

} // namespace trimlab
