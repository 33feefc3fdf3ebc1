#include "core/trim/trim_membership.h"

#include "core/trim/dynamic_frame_scene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <thread>

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
    std::vector<char> result(points.size(), 0);
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        std::vector<RayHit> hits;
        for (std::size_t i = next++; i < points.size(); i = next++)
            result[i] = pointOnTrim(chain, points[i], normals[i], epsilon, hits) ? 1 : 0;
    };
    const unsigned threads =
        std::clamp(unsigned(points.size() / 16), 1u, std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& thread : pool)
        thread.join();
    return {result.begin(), result.end()};
}

} // namespace trimlab
