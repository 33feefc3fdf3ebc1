#pragma once
/// \file
/// The vertex graph of a triangle mesh: vertices joined by the mesh edges (thesis
/// Definition 3.2 uses (u, v) ∈ E). Segments, clusters and over-segmentation classes are
/// connected in this graph.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Compressed adjacency lists: the neighbours of v are
/// `neighbors[offsets[v] .. offsets[v + 1])`, sorted ascending, without duplicates or v
/// itself. `offsets` has #V + 1 entries.
struct VertexGraph {
    std::vector<std::uint32_t> offsets{0};
    std::vector<std::uint32_t> neighbors;

    [[nodiscard]] std::size_t vertexCount() const { return offsets.size() - 1; }
    /// Undirected edges (each stored twice in `neighbors`).
    [[nodiscard]] std::size_t edgeCount() const { return neighbors.size() / 2; }
    [[nodiscard]] std::span<const std::uint32_t> neighborsOf(std::size_t v) const
    {
        return std::span<const std::uint32_t>(neighbors).subspan(offsets[v], offsets[v + 1] - offsets[v]);
    }
};

/// The graph of `vertexCount` vertices and the edges of `triangles` (indices < vertexCount;
/// degenerate triangles contribute their non-loop edges). O(F log F).
[[nodiscard]] VertexGraph buildVertexGraph(std::size_t vertexCount, std::span<const glm::uvec3> triangles);

/// A label per vertex and the number of labels: `labels` has #V entries in [0, count).
/// Used for pose partitions (C_i), over-segmentations and segmentations alike.
struct VertexLabeling {
    std::vector<std::uint32_t> labels;
    std::uint32_t count = 0;

    bool operator==(const VertexLabeling&) const = default;
};

/// Connected components of `graph`, numbered in order of their smallest vertex (isolated
/// vertices are components of their own).
[[nodiscard]] VertexLabeling connectedComponents(const VertexGraph& graph);

/// Renumbers `labels` (arbitrary values) so that labels appear in increasing order of
/// their first vertex: the canonical form every partition and segmentation is returned
/// in, which makes results comparable with ==.
[[nodiscard]] VertexLabeling canonicalLabeling(std::span<const std::uint32_t> labels);

/// True when every label of `labeling` forms one connected set of vertices in `graph`.
/// Labels that no vertex carries are ignored.
[[nodiscard]] bool labelsAreConnected(const VertexGraph& graph, const VertexLabeling& labeling);

} // namespace trimlab
