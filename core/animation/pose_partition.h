#pragma once
/// \file
/// Partitioning one pose by its feature (thesis 3.1: "partitioning of each pose is
/// precomputed in parallel using any of the numerous available features and clustering
/// methods"): the clusters C_i of pose p_i.

#include "core/animation/pose_features.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace trimlab {

enum class PartitionMethod {
    RegionGrowing, ///< region_growing_partition.h: fast, for real-time use
    Hierarchical,  ///< hierarchical_partition.h: top-down splitting, better clusters
};

struct PartitionSettings {
    PartitionMethod method = PartitionMethod::RegionGrowing;
    std::size_t clusters = 8; ///< requested clusters per pose, ≥ 1
    int iterations = 5;       ///< Lloyd steps of seeded region growing
};

/// The clusters of one pose: connected, canonical labels (see the two methods for when
/// the count differs from `settings.clusters`). `weights` are the #V vertex areas.
[[nodiscard]] VertexLabeling partitionPose(const VertexGraph& graph, const PoseFeature& feature,
                                           std::span<const double> weights, const PartitionSettings& settings);

/// "region-growing", "hierarchical" (command line and JSON), and back.
[[nodiscard]] std::string_view partitionMethodName(PartitionMethod method);
[[nodiscard]] std::optional<PartitionMethod> parsePartitionMethod(std::string_view name);

} // namespace trimlab
