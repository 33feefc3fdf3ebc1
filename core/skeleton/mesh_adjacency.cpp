#include "core/skeleton/mesh_adjacency.h"

#include <glm/geometric.hpp>

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

} // namespace trimlab
