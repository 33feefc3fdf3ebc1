#pragma once
/// \file
/// Multi-source region growing (thesis 3.3: the fast pose partitioning used for
/// real-time segmentation): seeds spread uniformly over the surface, regions grown by
/// feature similarity, seeds moved to their region's mean feature and regrown.

#include "core/animation/seeded_region_growing.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// `count` seeds by farthest-point sampling in hop distance: the first is the vertex
/// farthest from vertex 0, each next one the vertex farthest from all seeds so far
/// (vertices of components without a seed count as infinitely far, so every component
/// gets a seed while seeds last; ties: smaller index). Fewer seeds when the graph has
/// fewer vertices. O(count·E).
[[nodiscard]] std::vector<std::uint32_t> uniformSeeds(const VertexGraph& graph, std::size_t count);

/// Partitions the vertices into `clusters` connected clusters: uniformSeeds, then
/// refineRegions with `iterations` Lloyd steps (thesis 3.3 uses 5 for every method),
/// weighted by `weights` (#V vertex areas). A component that received no seed (more
/// components than clusters) becomes one extra cluster, so the result may have more
/// than `clusters` labels; it has fewer only when the mesh has fewer vertices.
/// Returns canonical labels (canonicalLabeling). `clusters` ≥ 1.
[[nodiscard]] VertexLabeling regionGrowingPartition(const VertexGraph& graph, const FeatureView& feature,
                                                    std::span<const double> weights, std::size_t clusters,
                                                    int iterations = 5);

/// Gives every vertex still marked kNoRegion in `regions` a new region per connected
/// piece of such vertices (numbered from `next` on). Used when seeds did not reach a
/// component.
void labelUnreached(const VertexGraph& graph, std::vector<std::uint32_t>& regions, std::uint32_t next);

} // namespace trimlab
