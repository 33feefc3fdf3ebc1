#include "core/skeleton/point_in_mesh.h"

#include "core/scene/scene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace trimlab {

namespace {

Scene singleObjectScene(const TriangleMesh& mesh)
{
    Scene scene;
    scene.objects.push_back(SceneObject{"skeleton input", mesh, glm::dmat4(1.0)});
    return scene;
}

} // namespace

PointInMesh::PointInMesh(const TriangleMesh& mesh) : m_bvh(singleObjectScene(mesh)), m_bounds(computeBounds(mesh))
{
}

bool PointInMesh::contains(const glm::dvec3& p) const
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        return false;
    // Directions away from the axes and from each other, so no ray runs along a
    // coordinate plane that generated or scanned meshes are often aligned with.
    static const glm::dvec3 kDirections[3] = {glm::normalize(glm::dvec3(0.5773, 0.6121, 0.5402)),
                                              glm::normalize(glm::dvec3(-0.7071, 0.3094, 0.6358)),
                                              glm::normalize(glm::dvec3(0.2133, -0.8747, 0.4350))};
    // Every crossing lies within the bounding sphere; a tight range keeps the BVH's
    // conservative t slack (relative to the range) from admitting boxes behind p.
    const double reach = glm::length(p - m_bounds.center()) + m_bounds.radius() + 1.0;
    // A crossing this close to p means p lies on the surface (e.g. a mesh vertex).
    const double onSurface = 1e-9 * (m_bounds.radius() + glm::length(p - m_bounds.center()));
    std::vector<RayHit> hits;
    int odd = 0;
    for (const glm::dvec3& direction : kDirections) {
        hits.clear();
        m_bvh.intersectAll(PixelRay{p, direction}, 0.0, reach, hits);
        for (const RayHit& hit : hits)
            if (hit.t <= onSurface)
                return false;
        odd += static_cast<int>(hits.size() % 2);
    }
    return odd >= 2;
}

std::optional<double> PointInMesh::nearestCrossing(const glm::dvec3& origin, const glm::dvec3& direction, double tMin,
                                                   double tMax) const
{
    const double reach = std::min(tMax, glm::length(origin - m_bounds.center()) + m_bounds.radius() + 1.0);
    const std::optional<RayHit> hit = m_bvh.intersectNearest(PixelRay{origin, direction}, tMin, reach);
    if (!hit)
        return std::nullopt;
    return hit->t;
}

bool PointInMesh::segmentInside(const glm::dvec3& p, const glm::dvec3& q) const
{
    if (!contains(p) || !contains(q))
        return false;
    const double length = glm::length(q - p);
    if (length == 0.0)
        return true;
    return !nearestCrossing(p, (q - p) / length, 0.0, length);
}

} // namespace trimlab
