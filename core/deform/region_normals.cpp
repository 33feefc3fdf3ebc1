#include "core/deform/region_normals.h"

#include "core/deform/local_vertex_map.h"
#include "core/mesh/corner_angle.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace trimlab::deform {

namespace {

// Σ over incident triangles, in ascending triangle order (as the global loop visits
// them), of the unit face normal times the corner angle at v.
glm::vec3 angleWeightedNormal(const BrushTopology& topology, std::span<const glm::vec3> positions, std::uint32_t v)
{
    glm::dvec3 sum(0.0);
    for (const std::uint32_t* f = topology.facesBegin(v); f != topology.facesEnd(v); ++f) {
        const glm::uvec3& t = topology.triangles()[*f];
        const glm::dvec3 p[3] = {glm::dvec3(positions[t[0]]), glm::dvec3(positions[t[1]]), glm::dvec3(positions[t[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double len = glm::length(n);
        if (len == 0.0 || !std::isfinite(len))
            continue;
        const glm::dvec3 unit = n / len;
        for (int i = 0; i < 3; ++i) {
            if (t[i] == v)
                sum += unit * cornerAngle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
        }
    }
    const double len = glm::length(sum);
    return len > 0.0 ? glm::vec3(sum / len) : glm::vec3(0.0f);
}

} // namespace

std::vector<glm::vec3> vertexNormalsOf(const BrushTopology& topology, std::span<const glm::vec3> positions,
                                       std::span<const std::uint32_t> vertices)
{
    if (positions.size() != topology.vertexCount())
        throw std::invalid_argument("vertexNormalsOf: positions do not match the topology");
    std::vector<glm::vec3> normals;
    normals.reserve(vertices.size());
    for (std::uint32_t v : vertices) {
        if (v >= topology.vertexCount())
            throw std::invalid_argument("vertexNormalsOf: vertex index out of range");
        normals.push_back(angleWeightedNormal(topology, positions, v));
    }
    return normals;
}

// The one-ring neighbours outside `moved` are few (the region's border) next to the
// region itself, so they are collected and sorted apart and then merged with the sorted
// region, instead of sorting every ring entry of the region.
std::vector<std::uint32_t> normalsAffectedBy(const BrushTopology& topology, std::span<const std::uint32_t> moved)
{
    std::vector<std::uint32_t> region(moved.begin(), moved.end());
    if (!std::is_sorted(region.begin(), region.end()))
        std::sort(region.begin(), region.end());
    region.erase(std::unique(region.begin(), region.end()), region.end());
    if (!region.empty() && region.back() >= topology.vertexCount())
        throw std::invalid_argument("normalsAffectedBy: vertex index out of range");

    LocalVertexMap<std::uint8_t> inRegion(region.size());
    for (std::uint32_t v : region)
        inRegion[v] = 1;
    std::vector<std::uint32_t> border;
    for (std::uint32_t v : region) {
        for (const std::uint32_t* u = topology.ringBegin(v); u != topology.ringEnd(v); ++u) {
            if (inRegion.find(*u) == nullptr)
                border.push_back(*u);
        }
    }
    std::sort(border.begin(), border.end());
    border.erase(std::unique(border.begin(), border.end()), border.end());

    std::vector<std::uint32_t> affected(region.size() + border.size());
    std::merge(region.begin(), region.end(), border.begin(), border.end(), affected.begin());
    return affected;
}

void recomputeNormals(const BrushTopology& topology, std::span<const glm::vec3> positions,
                      std::span<const std::uint32_t> vertices, std::span<glm::vec3> normals)
{
    if (positions.size() != topology.vertexCount() || normals.size() != topology.vertexCount())
        throw std::invalid_argument("recomputeNormals: positions or normals do not match the topology");
    for (std::uint32_t v : vertices) {
        if (v >= topology.vertexCount())
            throw std::invalid_argument("recomputeNormals: vertex index out of range");
        normals[v] = angleWeightedNormal(topology, positions, v);
    }
}

std::vector<std::uint32_t> updateRegionNormals(const BrushTopology& topology, std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> moved, std::span<glm::vec3> normals)
{
    std::vector<std::uint32_t> affected = normalsAffectedBy(topology, moved);
    recomputeNormals(topology, positions, affected, normals);
    return affected;
}

} // namespace trimlab::deform
