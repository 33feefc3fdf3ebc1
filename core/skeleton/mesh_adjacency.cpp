#include "core/skeleton/mesh_adjacency.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>

namespace trimlab {

VertexAdjacency vertexAdjacency(const TriangleMesh& mesh)
{
    VertexAdjacency adjacency(mesh.positions.size());
    const auto link = [&](std::uint32_t a, std::uint32_t b) {
        const double length = glm::length(glm::dvec3(mesh.positions[a]) - glm::dvec3(mesh.positions[b]));
        adjacency[a].emplace_back(b, length);
        adjacency[b].emplace_back(a, length);
    };
    for (const glm::uvec3& t : mesh.triangles) {
        link(t.x, t.y);
        link(t.y, t.z);
        link(t.z, t.x);
    }
    return adjacency;
}

std::vector<std::uint32_t> cheapestPath(const VertexAdjacency& graph, const std::vector<PathEnd>& from,
                                        const std::vector<PathEnd>& to)
{
    constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    std::vector<double> cost(graph.size(), std::numeric_limits<double>::infinity());
    std::vector<std::uint32_t> previous(graph.size(), none);
    std::unordered_map<std::uint32_t, double> lastStep;
    for (const PathEnd& end : to)
        if (const auto [at, added] = lastStep.try_emplace(end.vertex, end.cost); !added)
            at->second = std::min(at->second, end.cost);
    using Entry = std::pair<double, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (const PathEnd& start : from)
        if (start.cost < cost[start.vertex]) {
            cost[start.vertex] = start.cost;
            queue.emplace(start.cost, start.vertex);
        }
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t bestEnd = none;
    while (!queue.empty()) {
        const auto [c, v] = queue.top();
        queue.pop();
        if (c > cost[v])
            continue;
        if (c >= best) // every path still open costs at least the best found
            break;
        if (const auto last = lastStep.find(v); last != lastStep.end() && c + last->second < best) {
            best = c + last->second;
            bestEnd = v;
        }
        for (const auto& [w, step] : graph[v])
            if (c + step < cost[w]) {
                cost[w] = c + step;
                previous[w] = v;
                queue.emplace(cost[w], w);
            }
    }
    std::vector<std::uint32_t> path;
    for (std::uint32_t v = bestEnd; v != none; v = previous[v])
        path.push_back(v);
    std::reverse(path.begin(), path.end());
    return path;
}

} // namespace trimlab
