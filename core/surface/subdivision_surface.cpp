#include "core/surface/subdivision_surface.h"

#include "core/surface/subdivision_refinement.h"

#include "core/mesh/corner_angle.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

void requireSettings(const SubdivisionCage& cage, SubdivisionSettings settings)
{
    if (settings.level < 0 || settings.level > SubdivisionSurface::kMaxLevel)
        throw SubdivisionError("subdivision level " + std::to_string(settings.level) + " is outside 0 to " +
                               std::to_string(SubdivisionSurface::kMaxLevel));
    const std::size_t triangles = predictedTriangleCount(cage, settings.level);
    if (triangles > SubdivisionSurface::kMaxTriangles)
        throw SubdivisionError("subdivision level " + std::to_string(settings.level) + " of this cage would make " +
                               std::to_string(triangles) + " triangles (at most " +
                               std::to_string(SubdivisionSurface::kMaxTriangles) + "); use a lower level");
}

glm::dvec3 applyRow(const SubdivisionSurface::StencilRows& rows, std::size_t v, std::span<const glm::dvec3> cage)
{
    glm::dvec3 sum(0.0);
    for (std::size_t k = rows.offsets[v]; k < rows.offsets[v + 1]; ++k)
        sum += rows.entries[k].weight * cage[rows.entries[k].cageVertex];
    return sum;
}

} // namespace

SubdivisionSurface::SubdivisionSurface(const SubdivisionCage& cage, SubdivisionSettings settings)
    : m_settings(settings), m_scheme(cage.scheme), m_cageVertexCount(cage.vertexCount())
{
    validateCage(cage);
    requireSettings(cage, settings);
    SubdivisionTables tables = buildSubdivisionTables(cage, settings);
    m_position = std::move(tables.position);
    m_tangentU = std::move(tables.tangentU);
    m_tangentV = std::move(tables.tangentV);
    m_locations = std::move(tables.locations);
    m_mesh.triangles = std::move(tables.triangles);
    const std::size_t n = tables.outputVertexCount;
    m_mesh.positions.resize(n);
    m_positions.resize(n);
    m_normals.resize(n);
    if (settings.mode == SubdivisionMode::Limit) {
        m_tangentsU.resize(n);
        m_tangentsV.resize(n);
    }
    buildSupport();
    if (settings.mode == SubdivisionMode::Uniform)
        buildVertexTriangles();
    evaluate(cage.positions);
}

void SubdivisionSurface::buildSupport()
{
    std::vector<std::size_t> counts(m_cageVertexCount + 1, 0);
    for (const StencilWeight& w : m_position.entries)
        ++counts[w.cageVertex + 1];
    std::partial_sum(counts.begin(), counts.end(), counts.begin());
    m_supportOffsets = counts;
    m_support.resize(m_position.entries.size());
    const std::size_t outputs = m_position.offsets.size() - 1;
    for (std::size_t v = 0; v < outputs; ++v) // ascending v keeps every support sorted
        for (std::size_t k = m_position.offsets[v]; k < m_position.offsets[v + 1]; ++k)
            m_support[counts[m_position.entries[k].cageVertex]++] = std::uint32_t(v);
}

void SubdivisionSurface::buildVertexTriangles()
{
    std::vector<std::size_t> counts(m_positions.size() + 1, 0);
    for (const glm::uvec3& t : m_mesh.triangles)
        for (int i = 0; i < 3; ++i)
            ++counts[t[i] + 1];
    std::partial_sum(counts.begin(), counts.end(), counts.begin());
    m_vertexTriangleOffsets = counts;
    m_vertexTriangles.resize(3 * m_mesh.triangles.size());
    for (std::size_t f = 0; f < m_mesh.triangles.size(); ++f)
        for (int i = 0; i < 3; ++i)
            m_vertexTriangles[counts[m_mesh.triangles[f][i]]++] = std::uint32_t(f);
}

// The normal vertexNormals() gives `v`, from its own triangles only: the same terms summed
// in the same (ascending triangle) order, so a local update agrees to the bit.
glm::vec3 SubdivisionSurface::angleWeightedNormal(std::uint32_t v) const
{
    glm::dvec3 sum(0.0);
    for (std::size_t k = m_vertexTriangleOffsets[v]; k < m_vertexTriangleOffsets[v + 1]; ++k) {
        const glm::uvec3& t = m_mesh.triangles[m_vertexTriangles[k]];
        const glm::dvec3 p[3] = {glm::dvec3(m_mesh.positions[t[0]]), glm::dvec3(m_mesh.positions[t[1]]),
                                 glm::dvec3(m_mesh.positions[t[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(n);
        if (length == 0.0 || !std::isfinite(length))
            continue;
        const int i = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
        sum += (n / length) * cornerAngle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
    }
    const double length = glm::length(sum);
    return length > 0.0 ? glm::vec3(sum / length) : glm::vec3(0.0f);
}

void SubdivisionSurface::evaluate(std::span<const glm::dvec3> cagePositions)
{
    std::vector<std::uint32_t> all(m_positions.size());
    std::iota(all.begin(), all.end(), 0u);
    requireCage(cagePositions);
    applyStencils(cagePositions, all);
    updateNormals(all);
}

std::vector<std::uint32_t> SubdivisionSurface::update(std::span<const glm::dvec3> cagePositions,
                                                      std::span<const std::uint32_t> movedCageVertices)
{
    requireCage(cagePositions);
    std::vector<std::uint32_t> moved;
    for (const std::uint32_t c : movedCageVertices) {
        if (c >= m_cageVertexCount)
            throw std::invalid_argument("moved cage vertex " + std::to_string(c) + " is not below the cage's " +
                                        std::to_string(m_cageVertexCount) + " vertices");
        const std::span<const std::uint32_t> s = support(c);
        moved.insert(moved.end(), s.begin(), s.end());
    }
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    applyStencils(cagePositions, moved);
    updateNormals(moved);
    return moved;
}

void SubdivisionSurface::requireCage(std::span<const glm::dvec3> cagePositions) const
{
    if (cagePositions.size() != m_cageVertexCount)
        throw std::invalid_argument("the surface was built for " + std::to_string(m_cageVertexCount) +
                                    " cage vertices, but " + std::to_string(cagePositions.size()) + " were given");
    for (std::size_t c = 0; c < cagePositions.size(); ++c) {
        const glm::dvec3& p = cagePositions[c];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("cage vertex " + std::to_string(c) + " has a non-finite coordinate");
    }
}

void SubdivisionSurface::applyStencils(std::span<const glm::dvec3> cage, std::span<const std::uint32_t> vertices)
{
    const bool limit = m_settings.mode == SubdivisionMode::Limit;
    for (const std::uint32_t v : vertices) {
        m_positions[v] = applyRow(m_position, v, cage);
        m_mesh.positions[v] = glm::vec3(m_positions[v]);
        if (limit) {
            m_tangentsU[v] = applyRow(m_tangentU, v, cage);
            m_tangentsV[v] = applyRow(m_tangentV, v, cage);
        }
    }
}

void SubdivisionSurface::updateNormals(std::span<const std::uint32_t> vertices)
{
    if (m_settings.mode == SubdivisionMode::Uniform) {
        if (vertices.size() == m_positions.size()) {
            m_normals = vertexNormals(m_mesh);
            return;
        }
        // A moved vertex turns the normals of its one-ring too (marked, not sorted: the
        // ring holds each vertex about six times).
        std::vector<bool> inRing(m_positions.size(), false);
        for (const std::uint32_t v : vertices)
            for (std::size_t k = m_vertexTriangleOffsets[v]; k < m_vertexTriangleOffsets[v + 1]; ++k)
                for (int i = 0; i < 3; ++i) {
                    const std::uint32_t u = m_mesh.triangles[m_vertexTriangles[k]][i];
                    if (!inRing[u]) {
                        inRing[u] = true;
                        m_normals[u] = angleWeightedNormal(u);
                    }
                }
        return;
    }
    bool degenerate = false;
    for (const std::uint32_t v : vertices) {
        const glm::dvec3 n = glm::cross(m_tangentsU[v], m_tangentsV[v]);
        const double length = glm::length(n);
        // Relative test: tangents that are (nearly) parallel or zero give no direction.
        if (length > 1e-12 * glm::length(m_tangentsU[v]) * glm::length(m_tangentsV[v]) && length > 0.0) {
            m_normals[v] = glm::vec3(n / length);
        } else {
            m_normals[v] = glm::vec3(0.0f);
            degenerate = true;
        }
    }
    if (!degenerate)
        return;
    const std::vector<glm::vec3> fallback = vertexNormals(m_mesh);
    for (const std::uint32_t v : vertices)
        if (m_normals[v] == glm::vec3(0.0f))
            m_normals[v] = fallback[v];
}

std::span<const std::uint32_t> SubdivisionSurface::support(std::uint32_t cageVertex) const
{
    if (cageVertex >= m_cageVertexCount)
        return {};
    return std::span<const std::uint32_t>(m_support).subspan(
        m_supportOffsets[cageVertex], m_supportOffsets[cageVertex + 1] - m_supportOffsets[cageVertex]);
}

std::span<const StencilWeight> SubdivisionSurface::positionStencil(std::uint32_t v) const
{
    return std::span<const StencilWeight>(m_position.entries)
        .subspan(m_position.offsets[v], m_position.offsets[v + 1] - m_position.offsets[v]);
}

std::size_t SubdivisionSurface::stencilEntryCount() const
{
    return m_position.entries.size() + m_tangentU.entries.size() + m_tangentV.entries.size();
}

} // namespace trimlab
