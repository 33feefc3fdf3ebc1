#pragma once
/// \file
/// Top-down hierarchical clustering of one pose (thesis 3.3, after de Aguiar et al.'s
/// variant [41]): start with one cluster per connected component and split, one at a
/// time, the cluster whose feature varies most, until the requested number of clusters
/// exists.

#include "core/animation/seeded_region_growing.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <span>

namespace trimlab {

/// Partitions the vertices into `clusters` connected clusters (more when the mesh has
/// more components; fewer when no cluster can be split further because its feature is
/// constant or it has a single vertex).
/// - The cluster to split is the one with the largest weighted sum of squared feature
///   deviations Σ w_v·|f_v − mean|² (`weights`: #V vertex areas; ties: smaller label).
/// - A split projects the cluster's features on their principal axis (1D features: the
///   value itself) and seeds two regions at the vertices nearest the weighted 10th and
///   90th percentiles of the projection (percentiles, not the extremes, so that one noisy
///   vertex cannot take a whole cluster), then refines them with `iterations` Lloyd
///   steps of seeded region growing inside the cluster, so both halves stay connected.
/// Returns canonical labels (canonicalLabeling). `clusters` ≥ 1. O(clusters·V log V).
[[nodiscard]] VertexLabeling hierarchicalPartition(const VertexGraph& graph, const FeatureView& feature,
                                                   std::span<const double> weights, std::size_t clusters,
                                                   int iterations = 5);

} // namespace trimlab
