#include "core/deform/brush_stroke.h"

#include "core/deform/angle_attenuation.h"
#include "core/deform/brush_settings_check.h"
#include "core/deform/closest_surface_point.h"
#include "core/deform/falloff.h"
#include "core/deform/local_geodesics.h"
#include "core/deform/region_normals.h"
#include "core/deform/region_smoothing.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab::deform {

namespace {

bool isFinite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void requireVertexCount(const BrushTopology& topology, std::size_t count, const char* where)
{
    if (count != topology.vertexCount())
        throw std::invalid_argument(std::string(where) + ": " + std::to_string(count) + " positions for a mesh of " +
                                    std::to_string(topology.vertexCount()) + " vertices");
}

// Barycentric coordinates of p projected into the plane of (a, b, c); thirds for a
// degenerate triangle.
glm::dvec3 barycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 e0 = b - a, e1 = c - a, q = p - a;
    const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const double denom = d00 * d11 - d01 * d01;
    if (!(denom > 0.0))
        return glm::dvec3(1.0 / 3.0);
    const double q0 = glm::dot(q, e0), q1 = glm::dot(q, e1);
    const double v = (d11 * q0 - d01 * q1) / denom;
    const double w = (d00 * q1 - d01 * q0) / denom;
    return {1.0 - v - w, v, w};
}

// The surface normal at the anchor: the corners' angle-weighted normals blended
// barycentrically (so an anchor on a vertex has exactly that vertex's normal, and its
// angle term is exactly 1), or the face normal where they cancel.
glm::dvec3 anchorNormal(const BrushTopology& topology, std::span<const glm::vec3> positions, std::uint32_t triangle,
                        const glm::dvec3& anchor)
{
    const glm::uvec3& t = topology.triangles()[triangle];
    const std::uint32_t corners[3] = {t.x, t.y, t.z};
    const std::vector<glm::vec3> normals = vertexNormalsOf(topology, positions, corners);
    const glm::dvec3 a(positions[t.x]), b(positions[t.y]), c(positions[t.z]);
    const glm::dvec3 w = barycentric(anchor, a, b, c);
    const glm::dvec3 blend = w.x * glm::dvec3(normals[0]) + w.y * glm::dvec3(normals[1]) + w.z * glm::dvec3(normals[2]);
    if (glm::length(blend) > 0.0)
        return glm::normalize(blend);
    const glm::dvec3 face = glm::cross(b - a, c - a);
    return glm::length(face) > 0.0 ? glm::normalize(face) : glm::dvec3(0.0);
}

// Geodesic distances below `radius` from `anchor` on `triangle` at `positions`, seeded
// from the triangle's corners.
LocalDistances distancesFrom(const BrushTopology& topology, std::span<const glm::vec3> positions,
                             std::uint32_t triangle, const glm::dvec3& anchor, double radius)
{
    const glm::uvec3& t = topology.triangles()[triangle];
    GeodesicSeed seeds[3];
    for (int i = 0; i < 3; ++i)
        seeds[i] = {t[i], glm::distance(anchor, glm::dvec3(positions[t[i]]))};
    return localGeodesicDistances(topology, positions, seeds, radius);
}

// The anchor's point on the rest surface: the same barycentric point of its triangle.
glm::dvec3 restAnchor(const BrushTopology& topology, std::span<const glm::vec3> positions, std::uint32_t triangle,
                      const glm::dvec3& anchor)
{
    const glm::uvec3& t = topology.triangles()[triangle];
    const glm::dvec3 w =
        barycentric(anchor, glm::dvec3(positions[t.x]), glm::dvec3(positions[t.y]), glm::dvec3(positions[t.z]));
    const std::vector<glm::vec3>& rest = topology.restPositions();
    return w.x * glm::dvec3(rest[t.x]) + w.y * glm::dvec3(rest[t.y]) + w.z * glm::dvec3(rest[t.z]);
}

// Each vertex's distance is the smaller of its geodesic distances on the current surface
// and on the rest surface. On the current surface alone, a stroke that starts inside an
// earlier dent reaches only the one or two vertices of its stretched walls and pulls them
// into spikes; the rest surface's distances give it the patch a stroke there would have
// grabbed before the dent, and where earlier strokes compressed the surface the current
// distances reach further.
InfluenceRegion influenceRegion(const BrushTopology& topology, std::span<const glm::vec3> positions,
                                std::uint32_t triangle, const glm::dvec3& anchor, const BrushSettings& settings)
{
    const LocalDistances current = distancesFrom(topology, positions, triangle, anchor, settings.radius);
    const LocalDistances rest = distancesFrom(topology, topology.restPositions(), triangle,
                                              restAnchor(topology, positions, triangle, anchor), settings.radius);
    InfluenceRegion region;
    std::size_t i = 0, j = 0; // both lists are sorted by vertex
    while (i < current.vertices.size() || j < rest.vertices.size()) {
        const bool takeCurrent =
            j == rest.vertices.size() || (i < current.vertices.size() && current.vertices[i] <= rest.vertices[j]);
        const bool takeRest =
            i == current.vertices.size() || (j < rest.vertices.size() && rest.vertices[j] <= current.vertices[i]);
        const std::uint32_t v = takeCurrent ? current.vertices[i] : rest.vertices[j];
        double d = takeCurrent ? current.distances[i] : rest.distances[j];
        if (takeCurrent && takeRest)
            d = std::min(d, rest.distances[j]);
        region.vertices.push_back(v);
        region.geodesicDistance.push_back(d);
        i += takeCurrent ? 1 : 0;
        j += takeRest ? 1 : 0;
    }
    region.falloff.reserve(region.vertices.size());
    for (double d : region.geodesicDistance)
        region.falloff.push_back(falloff(settings.profile, d / settings.radius));
    return region;
}

} // namespace

BrushStroke::BrushStroke(const BrushTopology& topology, std::span<const glm::vec3> positions, const Stroke& stroke)
    : m_topology(&topology), m_settings(stroke.brush)
{
    requireValidBrushSettings(m_settings);
    requireVertexCount(topology, positions.size(), "BrushStroke");
    if (!isFinite(stroke.anchor))
        throw std::invalid_argument("BrushStroke: the anchor is not finite");
    if (stroke.anchorTriangle) {
        if (*stroke.anchorTriangle >= topology.triangles().size())
            throw std::invalid_argument("BrushStroke: anchor triangle " + std::to_string(*stroke.anchorTriangle) +
                                        " is out of range (" + std::to_string(topology.triangles().size()) +
                                        " triangles)");
        m_anchor = stroke.anchor;
        m_anchorTriangle = *stroke.anchorTriangle;
    } else {
        const SurfacePoint grabbed = closestSurfacePoint(positions, topology.triangles(), stroke.anchor);
        m_anchor = grabbed.point;
        m_anchorTriangle = grabbed.triangle;
    }

    m_anchorNormal = anchorNormal(topology, positions, m_anchorTriangle, m_anchor);
    m_region = influenceRegion(topology, positions, m_anchorTriangle, m_anchor, m_settings);
    m_patch = RegionPatch(topology, m_region.vertices);
    m_start.reserve(m_patch.size());
    for (std::size_t i = 0; i < m_patch.size(); ++i)
        m_start.emplace_back(positions[m_patch.global(i)]);
    m_startNormals = vertexNormalsOf(topology, positions, m_region.vertices);
    m_smoothingSteps.reserve(m_region.falloff.size());
    for (double f : m_region.falloff)
        m_smoothingSteps.push_back(m_settings.smoothingStep * f);
}

void BrushStroke::update(const glm::dvec3& drag, std::span<glm::vec3> positions) const
{
    requireVertexCount(*m_topology, positions.size(), "BrushStroke::update");
    if (!isFinite(drag))
        throw std::invalid_argument("BrushStroke::update: the drag is not finite");

    const double length = glm::length(drag);
    const glm::dvec3 direction = length > 0.0 ? drag / length : glm::dvec3(0.0);
    const glm::dvec3 pull = m_settings.strength * drag;
    std::vector<glm::dvec3> local = m_start;
    for (std::size_t r = 0; r < m_region.vertices.size(); ++r) {
        const double a = angleAttenuation(glm::dvec3(m_startNormals[r]), m_anchorNormal, direction);
        local[r] += (m_region.falloff[r] * a) * pull;
    }
    smoothRegion(m_patch, local, m_smoothingSteps, m_settings.smoothingWeights, m_settings.smoothingIterations);
    for (std::size_t r = 0; r < m_region.vertices.size(); ++r)
        positions[m_region.vertices[r]] = glm::vec3(local[r]);
}

Stroke BrushStroke::committed(const glm::dvec3& drag) const
{
    Stroke stroke;
    stroke.anchor = m_anchor;
    stroke.anchorTriangle = m_anchorTriangle;
    stroke.drag = drag;
    stroke.brush = m_settings;
    return stroke;
}

std::vector<std::uint32_t> applyStroke(const BrushTopology& topology, std::span<glm::vec3> positions,
                                       const Stroke& stroke)
{
    const BrushStroke brush(topology, positions, stroke);
    brush.update(stroke.drag, positions);
    return brush.region().vertices;
}

} // namespace trimlab::deform
