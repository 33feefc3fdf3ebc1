#pragma once
/// \file
/// The graph of labels (clusters or segments): two labels are neighbours when a mesh
/// edge joins vertices carrying them — N(S) in thesis 3.1.2 and the cluster graph the
/// colouring of 3.2.1 walks.

#include "core/animation/vertex_graph.h"

#include <cstdint>
#include <vector>

namespace trimlab {

/// Neighbour lists of the `labeling.count` labels, each sorted ascending without
/// duplicates. O(|E| log |E|).
[[nodiscard]] std::vector<std::vector<std::uint32_t>> labelAdjacency(const VertexGraph& graph,
                                                                     const VertexLabeling& labeling);

} // namespace trimlab
