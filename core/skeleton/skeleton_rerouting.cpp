#include "core/skeleton/skeleton_rerouting.h"

#include "core/skeleton/mesh_adjacency.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace trimlab {

namespace {

// The vertex whose inward chord midpoint the node sees inside, nearest to the node; the
// nearest few by distance are tried (a node near a thin gap may be nearer to the other
// side's surface, whose midpoint it cannot see).
std::optional<std::uint32_t> anchorVertex(const glm::dvec3& node, const TriangleMesh& mesh,
                                          const std::vector<std::optional<glm::dvec3>>& midpoints,
                                          const PointInMesh& inside)
{
    constexpr std::size_t kTried = 16;
    std::vector<std::pair<double, std::uint32_t>> nearest;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
        if (midpoints[v])
            nearest.emplace_back(glm::length(glm::dvec3(mesh.positions[v]) - node), v);
    const std::size_t count = std::min(kTried, nearest.size());
    std::partial_sort(nearest.begin(), nearest.begin() + std::ptrdiff_t(count), nearest.end());
    for (std::size_t i = 0; i < count; ++i)
        if (inside.segmentInside(node, *midpoints[nearest[i].second]))
            return nearest[i].second;
    return std::nullopt;
}

// From `points` (first and last: the edge's ends), the ones to keep as nodes: from each
// kept point, the farthest later point whose segment stays inside. Empty when some
// point cannot be left.
std::vector<glm::dvec3> visibleChain(const std::vector<glm::dvec3>& points, const PointInMesh& inside)
{
    std::vector<glm::dvec3> chain;
    std::size_t current = 0;
    while (current + 1 < points.size()) {
        std::size_t next = current;
        for (std::size_t j = current + 1; j < points.size(); ++j)
            if (inside.segmentInside(points[current], points[j]))
                next = j;
        if (next == current)
            return {};
        if (next + 1 < points.size())
            chain.push_back(points[next]);
        current = next;
    }
    return chain;
}

// The inside nodes replacing edge a–b (not counting a and b), or nullopt.
std::optional<std::vector<glm::dvec3>> insideRoute(const glm::dvec3& a, const glm::dvec3& b, const TriangleMesh& mesh,
                                                   const VertexAdjacency& adjacency,
                                                   const std::vector<std::optional<glm::dvec3>>& midpoints,
                                                   const PointInMesh& inside)
{
    const std::optional<std::uint32_t> from = anchorVertex(a, mesh, midpoints, inside);
    const std::optional<std::uint32_t> to = anchorVertex(b, mesh, midpoints, inside);
    if (!from || !to)
        return std::nullopt;
    const std::vector<std::uint32_t> path = cheapestPath(adjacency, {{*from, 0.0}}, {{*to, 0.0}});
    if (path.empty())
        return std::nullopt;
    std::vector<glm::dvec3> points{a};
    for (std::uint32_t v : path)
        if (midpoints[v] && inside.contains(*midpoints[v]))
            points.push_back(*midpoints[v]);
    points.push_back(b);
    std::vector<glm::dvec3> chain = visibleChain(points, inside);
    if (chain.empty() && !inside.segmentInside(a, b))
        return std::nullopt;
    return chain;
}

} // namespace

ReroutingResult rerouteLeavingEdges(CurveSkeleton& curve, const TriangleMesh& mesh,
                                    const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& inside)
{
    if (midpoints.size() != mesh.positions.size())
        throw std::invalid_argument("rerouteLeavingEdges: " + std::to_string(midpoints.size()) + " midpoints for " +
                                    std::to_string(mesh.positions.size()) + " vertices");
    ReroutingResult result;
    std::optional<VertexAdjacency> adjacency; // built at the first leaving edge
    std::vector<std::array<int, 2>> edges;
    for (const std::array<int, 2>& edge : curve.edges) {
        const glm::dvec3 a = curve.nodes[std::size_t(edge[0])];
        const glm::dvec3 b = curve.nodes[std::size_t(edge[1])];
        if (inside.segmentInside(a, b)) {
            edges.push_back(edge);
            continue;
        }
        if (!adjacency)
            adjacency = vertexAdjacency(mesh);
        const std::optional<std::vector<glm::dvec3>> route = insideRoute(a, b, mesh, *adjacency, midpoints, inside);
        if (!route) {
            edges.push_back(edge);
            ++result.kept;
            continue;
        }
        int previous = edge[0];
        for (const glm::dvec3& p : *route) {
            const int node = int(curve.nodes.size());
            curve.nodes.push_back(p);
            edges.push_back({std::min(previous, node), std::max(previous, node)});
            previous = node;
        }
        edges.push_back({std::min(previous, edge[1]), std::max(previous, edge[1])});
        result.nodesAdded += route->size();
        ++result.rerouted;
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    curve.edges = std::move(edges);
    return result;
}

} // namespace trimlab
