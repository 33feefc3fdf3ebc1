#pragma once
/// \file
/// The vertex graph of a triangle mesh with its edge lengths, for walks over the surface:
/// the rerouting's shortest paths (skeleton_rerouting.h) and the branch recovery's patches
/// and depths (branch_recovery.h); and the cheapest path over such a weighted graph, which
/// the chain routing also takes over its graph of medial points (medial_chain_routing.h).

#include "core/mesh/triangle_mesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace trimlab {

/// Per vertex, its neighbours and the lengths of the edges to them. An edge shared by two
/// triangles is listed twice (harmless for walks; not worth a sort).
using VertexAdjacency = std::vector<std::vector<std::pair<std::uint32_t, double>>>;

[[nodiscard]] VertexAdjacency vertexAdjacency(const TriangleMesh& mesh);

/// A vertex where a path may start or end, with the cost of getting there from the path's
/// true end (0 for a vertex that is the end).
struct PathEnd {
    std::uint32_t vertex = 0;
    double cost = 0.0;
};

/// Dijkstra over `graph` (costs ≥ 0): the vertices of the cheapest path from any of `from`
/// to any of `to`, counting the ends' costs; empty when none joins them.
[[nodiscard]] std::vector<std::uint32_t> cheapestPath(const VertexAdjacency& graph, const std::vector<PathEnd>& from,
                                                      const std::vector<PathEnd>& to);

} // namespace trimlab
