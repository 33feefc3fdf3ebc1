#include "core/animation/vertex_areas.h"

#include <glm/geometric.hpp>

namespace trimlab {

std::vector<double> vertexAreas(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles)
{
    std::vector<double> areas(positions.size(), 0.0);
    for (const glm::uvec3& t : triangles) {
        const glm::dvec3 a(positions[t.x]);
        const glm::dvec3 b(positions[t.y]);
        const glm::dvec3 c(positions[t.z]);
        const double third = glm::length(glm::cross(b - a, c - a)) / 6.0;
        areas[t.x] += third;
        areas[t.y] += third;
        areas[t.z] += third;
    }
    return areas;
}

std::vector<double> labelAreas(std::span<const std::uint32_t> labels, std::size_t count, std::span<const double> areas)
{
    std::vector<double> sums(count, 0.0);
    for (std::size_t v = 0; v < labels.size(); ++v)
        sums[labels[v]] += areas[v];
    return sums;
}

} // namespace trimlab
