#pragma once
/// \file
/// The join of pose partitions, kept incrementally (thesis 3.2.2 real-time segmentation
/// and 3.2.6 edit propagation): the partitions C_1 … C_k in pose order and, for every
/// prefix, the over-segmentation OS(p_1 … p_i) — the segments segment(v, i) of
/// Definition 3.3 — which p2p-cleaning reads.

#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace trimlab {

class PoseJoin {
public:
    /// An empty join (k = 0) on `graph`; level 0 is the connected components (segment(v, 0):
    /// with no pose every CAV is empty, so only connectivity separates vertices).
    explicit PoseJoin(std::shared_ptr<const VertexGraph> graph);

    /// Joins a new last partition C_{k+1}: one pruned BFS over the pairs
    /// (segment(v, k), C_{k+1}(v)), O(|E|). Throws std::invalid_argument when the
    /// partition does not have #V labels.
    void append(VertexLabeling partition);

    /// Replaces partition `index` (0-based: C_{index+1}) and recomputes the prefix levels
    /// from there on, O((k − index)·|E|); the partitions themselves are not recomputed.
    /// Equals building the join from scratch with the new partition (tested).
    void replace(std::size_t index, VertexLabeling partition);

    /// Replaces several partitions (index, partition) at once and recomputes the levels
    /// once, from the smallest index on. Throws like replace, before changing anything.
    void replace(std::vector<std::pair<std::size_t, VertexLabeling>> partitions);

    [[nodiscard]] std::size_t partitionCount() const { return m_partitions.size(); }
    /// C_{i+1} for i < partitionCount().
    [[nodiscard]] const VertexLabeling& partition(std::size_t i) const { return m_partitions.at(i); }
    /// segment(·, i) for i ≤ partitionCount(); level(0) = connected components.
    [[nodiscard]] const VertexLabeling& level(std::size_t i) const { return m_levels.at(i); }
    /// OS(A) = level(k): the over-segmentation of all joined partitions.
    [[nodiscard]] const VertexLabeling& overSegmentation() const { return m_levels.back(); }
    [[nodiscard]] const VertexGraph& graph() const { return *m_graph; }
    [[nodiscard]] const std::shared_ptr<const VertexGraph>& sharedGraph() const { return m_graph; }

private:
    void requireSize(const VertexLabeling& partition) const;

    std::shared_ptr<const VertexGraph> m_graph;
    std::vector<VertexLabeling> m_partitions;
    std::vector<VertexLabeling> m_levels;
};

} // namespace trimlab
