#include "core/solid/solid_measures.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>

namespace trimlab {

namespace {

glm::dvec3 at(const TriangleMesh& mesh, std::uint32_t v)
{
    return glm::dvec3(mesh.positions[v]);
}

// Where the edge between a and b crosses the plane, computed from the smaller index first
// so that both triangles of the edge get the same point.
glm::dvec3 edgeCrossing(const TriangleMesh& mesh, const ClipPlane& plane, std::uint32_t a, std::uint32_t b)
{
    if (b < a)
        std::swap(a, b);
    const glm::dvec3 p = at(mesh, a);
    const glm::dvec3 q = at(mesh, b);
    const double sp = plane.evaluate(p);
    const double sq = plane.evaluate(q);
    return p + (q - p) * (sp / (sp - sq));
}

} // namespace

double surfaceArea(const TriangleMesh& mesh)
{
    double area = 0.0;
    for (const glm::uvec3& t : mesh.triangles)
        area += 0.5 * glm::length(glm::cross(at(mesh, t.y) - at(mesh, t.x), at(mesh, t.z) - at(mesh, t.x)));
    return area;
}

double crossSectionArea(const TriangleMesh& mesh, const ClipPlane& plane)
{
    const glm::dvec3 n = glm::normalize(plane.normal);
    const ClipPlane unit{true, n, plane.offset / glm::length(plane.normal)};
    const glm::dvec3 origin = -unit.offset * n; // a point of the plane
    double twiceArea = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        std::array<bool, 3> above{};
        for (int i = 0; i < 3; ++i)
            above[std::size_t(i)] = unit.evaluate(at(mesh, t[i])) >= 0.0;
        if (above[0] == above[1] && above[1] == above[2])
            continue;
        // The vertex alone on its side, and the two edges from it that cross the plane.
        const int lone = above[0] == above[1] ? 2 : above[0] == above[2] ? 1 : 0;
        const std::uint32_t v = t[lone];
        const std::uint32_t next = t[(lone + 1) % 3];
        const std::uint32_t previous = t[(lone + 2) % 3];
        glm::dvec3 p = edgeCrossing(mesh, unit, v, next) - origin;
        glm::dvec3 q = edgeCrossing(mesh, unit, previous, v) - origin;
        // Run with the inside on the left seen from +n: along n × (outward normal).
        const glm::dvec3 normal = glm::cross(at(mesh, t.y) - at(mesh, t.x), at(mesh, t.z) - at(mesh, t.x));
        if (glm::dot(q - p, glm::cross(n, normal)) < 0.0)
            std::swap(p, q);
        twiceArea += glm::dot(n, glm::cross(p, q));
    }
    return 0.5 * twiceArea;
}

SolidMeasures measureTrimmedSolid(const Scene& scene, const TrimSettings& settings, const TaskControl& control)
{
    const TrimmedSolid solid = trimmedSolid(scene, settings, control);
    SolidMeasures measures;
    measures.stats = solid.stats;
    measures.volume = solid.stats.signedVolume;
    measures.area = surfaceArea(solid.mesh);
    const ClipSet clips = settings.clipSet();
    for (std::size_t i = 0; i < clips.planes.size(); ++i)
        if (clips.planes[i].enabled)
            measures.sections.push_back({int(i), crossSectionArea(solid.mesh, clips.planes[i])});
    return measures;
}

} // namespace trimlab
