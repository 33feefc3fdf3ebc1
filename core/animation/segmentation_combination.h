#pragma once
/// \file
/// Combining segmentations (thesis 3.2.5): segmentations of one animation computed from
/// different features, or of different animations of the same mesh (through a vertex
/// bijection), are joined like pose partitions and cleaned with p2p-cleaning.

#include "core/animation/pose_features.h"
#include "core/animation/pose_partition.h"
#include "core/animation/vertex_graph.h"

#include <memory>
#include <span>
#include <vector>

namespace trimlab {

/// Joins `segmentations` (each #V labels, in the given order, which is the cleaning's
/// pose order) into their over-segmentation and cleans it with `h` (p2p_cleaning.h).
/// The inputs need not be connected per label: the join splits disconnected labels.
/// `areas`: #V vertex areas. Throws std::invalid_argument on size mismatches.
[[nodiscard]] VertexLabeling combineSegmentations(std::shared_ptr<const VertexGraph> graph,
                                                  std::span<const double> areas,
                                                  std::span<const VertexLabeling> segmentations, double h);

/// A segmentation of animation B carried over to animation A: vertex v of A gets the
/// label of vertex bijection[v] of B. `bijection` must be a permutation of 0 … #V−1
/// (std::invalid_argument otherwise). Canonical labels.
[[nodiscard]] VertexLabeling transferLabeling(const VertexLabeling& labelingOfB,
                                              std::span<const std::uint32_t> bijection);

/// The numerical mean of several poses' features (thesis 3.2.5: "a unique global
/// segmentation is computed from each feature using the numerical mean of the per-pose
/// values"). All must have the same size and dimension; pose is set to 0.
[[nodiscard]] PoseFeature meanFeature(std::span<const PoseFeature> features);

/// A global segmentation: partitionPose applied to meanFeature(features).
[[nodiscard]] VertexLabeling globalSegmentation(const VertexGraph& graph, std::span<const PoseFeature> features,
                                                std::span<const double> areas, const PartitionSettings& settings);

} // namespace trimlab
