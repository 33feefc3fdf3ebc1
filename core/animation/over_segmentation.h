#pragma once
/// \file
/// The over-segmentation of a mesh animation (thesis 3.1.1, Definitions 3.1–3.3,
/// Algorithm 3.1): the maximal connected sets of vertices whose clustering animation
/// vectors cav(v) = (m_1, …, m_k) — the cluster of v in every pose partition — are equal.

#include "core/animation/vertex_graph.h"

#include <span>
#include <vector>

namespace trimlab {

/// Algorithm 3.1: one pruned breadth-first search per new segment, crossing an edge (u, v)
/// only when cav(u) = cav(v), each edge examined once from each side: O(|E|·k) for k
/// partitions (the CAV comparison), O(|E|) for a fixed k. Segments are numbered in order
/// of their smallest vertex.
/// The thesis's listing walks the vertex list in index order and assigns neighbours
/// without a queue, which can give a vertex's segment to a later one (a–b–c listed as a,
/// c, b puts a apart from b and c); a real BFS queue gives the equivalence classes of
/// TNS_k that Definition 3.3 asks for.
/// Every partition must have #V labels (std::invalid_argument otherwise). With no
/// partitions the result is the connected components.
[[nodiscard]] VertexLabeling overSegmentation(const VertexGraph& graph, std::span<const VertexLabeling> partitions);

/// The same for two labelings: the classes of TNS over the pair (a(v), b(v)). This is
/// one step of the incremental join (over-segmentation so far ⋈ new partition, thesis
/// 3.2.2), of the variable segmentation (C_t ⋈ C_{t+1}) and of combining two
/// segmentations (3.2.5).
[[nodiscard]] VertexLabeling joinLabelings(const VertexGraph& graph, const VertexLabeling& a, const VertexLabeling& b);

} // namespace trimlab
