#include "core/skeleton/skeleton_refinement.h"

#include "core/util/parallel_for.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

constexpr std::size_t kVertexBlock = 1024;

struct Region {
    glm::dvec3 positionSum{0.0};
    std::size_t count = 0;
    glm::dvec3 midpointSum{0.0};
    std::size_t midpoints = 0;
};

std::vector<Region> regionsOf(const CurveSkeleton& curve, const TriangleMesh& mesh,
                              const std::vector<std::optional<glm::dvec3>>& midpoints)
{
    if (curve.vertexNode.size() != mesh.vertexCount())
        throw std::invalid_argument("refineSkeleton: vertexNode has " + std::to_string(curve.vertexNode.size()) +
                                    " entries for " + std::to_string(mesh.vertexCount()) + " vertices");
    std::vector<Region> regions(curve.nodes.size());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const int k = curve.vertexNode[v];
        if (k < 0 || static_cast<std::size_t>(k) >= curve.nodes.size())
            throw std::invalid_argument("refineSkeleton: vertex " + std::to_string(v) + " maps to node " +
                                        std::to_string(k) + " of " + std::to_string(curve.nodes.size()));
        Region& region = regions[static_cast<std::size_t>(k)];
        region.positionSum += glm::dvec3(mesh.positions[v]);
        ++region.count;
        if (midpoints[v]) {
            region.midpointSum += *midpoints[v];
            ++region.midpoints;
        }
    }
    return regions;
}

} // namespace

std::vector<std::optional<glm::dvec3>> inwardChordMidpoints(const TriangleMesh& mesh, const PointInMesh& inside)
{
    const std::vector<glm::vec3> normals = vertexNormals(mesh);
    // Past the vertex's own triangles: a crossing closer than this is the ray leaving
    // through the fan it starts on (rounding), not the opposite wall.
    const double tMin = 1e-9 * inside.radius();
    std::vector<std::optional<glm::dvec3>> midpoints(mesh.vertexCount());
    const std::size_t blocks = (mesh.vertexCount() + kVertexBlock - 1) / kVertexBlock;
    parallelFor(blocks, 0, [&](std::size_t block) {
        const std::size_t end = std::min(mesh.vertexCount(), (block + 1) * kVertexBlock);
        for (std::size_t v = block * kVertexBlock; v < end; ++v) {
            const glm::dvec3 normal(normals[v]);
            if (glm::dot(normal, normal) < 0.5)
                continue; // isolated vertex: no normal
            const glm::dvec3 origin(mesh.positions[v]);
            if (const std::optional<double> t = inside.nearestCrossing(origin, -normal, tMin))
                midpoints[v] = origin - 0.5 * *t * normal;
        }
    });
    return midpoints;
}

std::optional<glm::dvec3> nearestInsideMidpoint(const glm::dvec3& p,
                                                const std::vector<std::optional<glm::dvec3>>& midpoints,
                                                const PointInMesh& inside)
{
    std::vector<std::pair<double, std::size_t>> byDistance;
    byDistance.reserve(midpoints.size());
    for (std::size_t v = 0; v < midpoints.size(); ++v)
        if (midpoints[v])
            byDistance.emplace_back(glm::length(*midpoints[v] - p), v);
    // Chord midpoints are inside but for rounding or a ray through a gap; a handful of
    // candidates always suffices, so sort only a prefix.
    constexpr std::size_t kCandidates = 32;
    const std::size_t prefix = std::min(kCandidates, byDistance.size());
    std::partial_sort(byDistance.begin(), byDistance.begin() + static_cast<std::ptrdiff_t>(prefix), byDistance.end());
    for (std::size_t i = 0; i < prefix; ++i)
        if (inside.contains(*midpoints[byDistance[i].second]))
            return *midpoints[byDistance[i].second];
    return std::nullopt;
}

std::size_t refineSkeleton(CurveSkeleton& curve, const TriangleMesh& mesh,
                           const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& inside)
{
    if (midpoints.size() != mesh.vertexCount())
        throw std::invalid_argument("refineSkeleton: " + std::to_string(midpoints.size()) + " chord midpoints for " +
                                    std::to_string(mesh.vertexCount()) + " vertices");
    const std::vector<Region> regions = regionsOf(curve, mesh, midpoints);
    std::vector<char> moved(curve.nodes.size(), 0);
    parallelFor(curve.nodes.size(), 0, [&](std::size_t k) {
        const Region& region = regions[k];
        if (region.count == 0)
            return;
        const glm::dvec3 centroid = region.positionSum / static_cast<double>(region.count);
        const glm::dvec3 sectionCentre =
            region.midpoints > 0 ? region.midpointSum / static_cast<double>(region.midpoints) : centroid;
        if (region.midpoints > 0 && inside.contains(sectionCentre)) {
            curve.nodes[k] = sectionCentre;
            moved[k] = 1;
        } else if (inside.contains(centroid)) {
            curve.nodes[k] = centroid; // v_k + d_k of eq. (11)
            moved[k] = 1;
        }
    });
    // (3) needs the region's own midpoints: one pass over the vertices for the nodes left.
    std::vector<double> nearest(curve.nodes.size(), std::numeric_limits<double>::infinity());
    std::vector<glm::dvec3> best(curve.nodes.size());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const auto k = static_cast<std::size_t>(curve.vertexNode[v]);
        if (moved[k] || !midpoints[v] || regions[k].midpoints == 0)
            continue;
        const glm::dvec3 centre = regions[k].midpointSum / static_cast<double>(regions[k].midpoints);
        const double distance = glm::length(*midpoints[v] - centre);
        if (distance < nearest[k] && inside.contains(*midpoints[v])) {
            nearest[k] = distance;
            best[k] = *midpoints[v];
        }
    }
    std::size_t count = 0;
    for (std::size_t k = 0; k < curve.nodes.size(); ++k) {
        if (!moved[k] && std::isfinite(nearest[k])) {
            curve.nodes[k] = best[k];
            moved[k] = 1;
        }
        if (!moved[k] && !inside.contains(curve.nodes[k]))
            if (const std::optional<glm::dvec3> anywhere = nearestInsideMidpoint(curve.nodes[k], midpoints, inside)) {
                curve.nodes[k] = *anywhere;
                moved[k] = 1;
            }
        count += moved[k];
    }
    return count;
}

} // namespace trimlab
