#pragma once
/// \file
/// The connectivity surgery of skeleton simplification (Berenguer & Moreno III.B, after
/// Au et al.): a 2-complex of vertices, edges and triangles in which edge collapses
/// merge one vertex into another, triangles that lose a corner disappear and edges that
/// lose their last triangle remain as skeleton edges. When no triangle is left the
/// complex is a 1D graph: the curve skeleton.

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

class CollapseComplex {
public:
    /// Vertices 0..#V−1 at `positions`, every edge and triangle of `triangles`
    /// (indices < #V, no repeated index in a face). Vertices no triangle uses stay
    /// isolated (no edges) and never take part in a collapse.
    CollapseComplex(std::span<const glm::dvec3> positions, std::span<const glm::uvec3> triangles);

    [[nodiscard]] std::size_t vertexCount() const { return m_positions.size(); }
    [[nodiscard]] bool alive(int v) const { return m_alive[static_cast<std::size_t>(v)] != 0; }
    [[nodiscard]] const glm::dvec3& position(int v) const { return m_positions[static_cast<std::size_t>(v)]; }
    /// The live vertices joined to `v` by an edge, without duplicates.
    [[nodiscard]] const std::vector<int>& neighbours(int v) const { return m_neighbours[static_cast<std::size_t>(v)]; }
    /// Whether the edge (a, b) exists and at least one live triangle contains it.
    [[nodiscard]] bool edgeHasTriangle(int a, int b) const;
    [[nodiscard]] std::size_t liveTriangleCount() const { return m_liveTriangles; }
    [[nodiscard]] std::size_t liveVertexCount() const { return m_liveVertices; }

    /// Merges `from` into `to` (an existing edge): triangles containing both disappear,
    /// the others and every edge of `from` move to `to` (merging with edges `to` already
    /// has); `to` keeps its position. `from` dies and representative(from) becomes `to`.
    void collapse(int from, int to);

    /// The live vertex that absorbed `v` (itself when alive). Amortised O(1).
    [[nodiscard]] int representative(int v);

private:
    void removeNeighbour(int v, int gone);
    void addNeighbour(int v, int other);
    void dropDeadTriangles(int v);

    std::vector<glm::dvec3> m_positions;
    std::vector<std::array<int, 3>> m_triangles;
    std::vector<char> m_triangleAlive;
    std::vector<std::vector<int>> m_vertexTriangles; // may list dead triangles until cleaned
    std::vector<std::vector<int>> m_neighbours;
    std::vector<char> m_alive;
    std::vector<int> m_absorbedBy; // −1 while alive
    std::size_t m_liveTriangles = 0;
    std::size_t m_liveVertices = 0;
};

} // namespace trimlab
