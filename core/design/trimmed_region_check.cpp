#include "core/design/trimmed_region_check.h"

#include "core/deform/region_normals.h"
#include "core/trim/trim_membership.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

TrimmedRegionCheck::TrimmedRegionCheck(const DynamicChain& chain, const glm::dmat4& model)
    : m_reference(chain), m_model(model)
{
}

std::vector<std::uint32_t> TrimmedRegionCheck::sample(std::span<const std::uint32_t> region,
                                                      const glm::uvec3& anchorTriangle)
{
    std::vector<std::uint32_t> vertices{anchorTriangle.x, anchorTriangle.y, anchorTriangle.z};
    const std::size_t spread = kMaxSamples - vertices.size();
    const std::size_t step = std::max<std::size_t>(1, (region.size() + spread - 1) / spread);
    for (std::size_t i = 0; i < region.size(); i += step)
        vertices.push_back(region[i]);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
}

std::vector<std::uint32_t> TrimmedRegionCheck::trimmedOff(const deform::BrushTopology& topology,
                                                          const std::vector<glm::vec3>& positions,
                                                          std::span<const std::uint32_t> vertices, double epsilon) const
{
    const std::vector<glm::vec3> normals = deform::vertexNormalsOf(topology, positions, vertices);
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(m_model)));
    // The offset along the normal is a world length; scale it like the model does.
    const double scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(m_model))));
    std::vector<glm::dvec3> worldPoints, worldNormals;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        worldPoints.push_back(glm::dvec3(m_model * glm::dvec4(glm::dvec3(positions[vertices[i]]), 1.0)));
        worldNormals.push_back(normalMatrix * glm::dvec3(normals[i]));
    }
    const std::vector<bool> onTrim = pointsOnTrim(m_reference, worldPoints, worldNormals, epsilon * scale);
    std::vector<std::uint32_t> off;
    for (std::size_t i = 0; i < vertices.size(); ++i)
        if (!onTrim[i])
            off.push_back(vertices[i]);
    return off;
}

} // namespace trimlab
