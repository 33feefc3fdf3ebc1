#include "core/trim/trim_membership.h"

#include "core/trim/dynamic_frame_scene.h"
#include "core/util/parallel_for.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace trimlab {

namespace {

constexpr double kFar = 1.0e30; // the ray leaves the scene: everything beyond is outside

bool pointOnTrim(const DynamicReferenceRenderer& chain, const glm::dvec3& point, const glm::dvec3& normal,
                 double epsilon, std::vector<RayHit>& hits)
{
    const double length = glm::length(normal);
    if (!(length > 0.0))
        return true;
    const glm::dvec3 direction = normal / length;
    const PixelRay ray{point - direction * epsilon, direction};
    const DynamicWalkResult walk = chain.walkRay(ray, 0.0, kFar, hits);
    // The first current-frame hit is the point's own surface (it lies epsilon ahead).
    std::ptrdiff_t firstCurrent = -1;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (inCurrent(frameClassOfObject(hits[i].objectId))) {
            firstCurrent = std::ptrdiff_t(i);
            break;
        }
    }
    return firstCurrent >= 0 && walk.walk.shownIndex == firstCurrent;
}

} // namespace

std::vector<bool> pointsOnTrim(const DynamicReferenceRenderer& chain, std::span<const glm::dvec3> points,
                               std::span<const glm::dvec3> normals, double epsilon)
{
    // Chunks of points on the shared pool (parallel_for.h), each reusing one hit list; an
    // exception in any chunk reaches the caller after every worker stopped.
    constexpr std::size_t kChunk = 64;
    std::vector<char> result(points.size(), 0);
    const std::size_t chunks = (points.size() + kChunk - 1) / kChunk;
    parallelFor(chunks, 0, [&](std::size_t chunk) {
        std::vector<RayHit> hits;
        const std::size_t end = std::min(points.size(), (chunk + 1) * kChunk);
        for (std::size_t i = chunk * kChunk; i < end; ++i)
            result[i] = pointOnTrim(chain, points[i], normals[i], epsilon, hits) ? 1 : 0;
    });
    return {result.begin(), result.end()};
}

} // namespace trimlab
