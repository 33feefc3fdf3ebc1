#include "core/trim/reference_diagnostics.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

double pixelDepthMargin(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimWalk& walk,
                        std::vector<double>& scratch)
{
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (span.empty)
        return kNone;
    scratch.clear();
    for (const RayHit& hit : sortedHits)
        scratch.push_back(hit.t);
    scratch.push_back(span.tStart);
    scratch.push_back(span.tEnd);
    // Another clipping plane nearly bounding the span instead (ClipSet).
    if (std::isfinite(span.startRunnerUp))
        scratch.push_back(span.startRunnerUp);
    if (std::isfinite(span.endRunnerUp))
        scratch.push_back(span.endRunnerUp);
    std::sort(scratch.begin(), scratch.end());
    const double deciding = walk.capPlane >= 0     ? span.tStart
                            : walk.shownIndex >= 0 ? sortedHits[std::size_t(walk.shownIndex)].t
                                                   : span.tEnd;
    auto first = std::lower_bound(scratch.begin(), scratch.end(), span.tStart);
    if (first != scratch.begin())
        --first;
    auto last = std::upper_bound(scratch.begin(), scratch.end(), deciding);
    if (last != scratch.end())
        ++last;
    double margin = kNone;
    for (auto it = first; it + 1 < last; ++it) {
        const double larger = std::max(std::abs(*it), std::abs(*(it + 1)));
        if (larger > 0.0)
            margin = std::min(margin, std::abs(*(it + 1) - *it) / larger);
    }
    return margin;
}

namespace {

// View-space point in pixelRay's basis: x right, y up, z = view depth (> 0 in front).
glm::dvec3 toView(const Camera& camera, const glm::dvec3& p)
{
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 q = p - camera.eye;
    return {glm::dot(q, right), glm::dot(q, up), glm::dot(q, forward)};
}

// Sutherland–Hodgman against depth >= zNear.
std::vector<glm::dvec3> clipAtNear(const std::array<glm::dvec3, 3>& view, double zNear)
{
    std::vector<glm::dvec3> out;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3& p = view[std::size_t(i)];
        const glm::dvec3& q = view[std::size_t((i + 1) % 3)];
        const bool pIn = p.z >= zNear;
        const bool qIn = q.z >= zNear;
        if (pIn)
            out.push_back(p);
        if (pIn != qIn)
            out.push_back(p + (q - p) * ((zNear - p.z) / (q.z - p.z)));
    }
    return out;
}

double distanceToSegment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b)
{
    const glm::dvec2 ab = b - a;
    const double lengthSquared = glm::dot(ab, ab);
    const double s = lengthSquared > 0.0 ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + ab * s));
}

} // namespace

double edgeDistancePixels(const Camera& camera, int width, int height, int x, int y,
                          const std::array<glm::dvec3, 3>& corners)
{
    const std::array<glm::dvec3, 3> view = {toView(camera, corners[0]), toView(camera, corners[1]),
                                            toView(camera, corners[2])};
    const std::vector<glm::dvec3> polygon = clipAtNear(view, camera.zNear);
    if (polygon.size() < 3)
        return std::numeric_limits<double>::infinity();
    const double tanHalf = std::tan(glm::radians(camera.fovyDegrees) * 0.5);
    const double aspect = double(width) / double(height);
    std::vector<glm::dvec2> screen;
    for (const glm::dvec3& p : polygon) {
        const double ndcX = p.x / p.z / (tanHalf * aspect);
        const double ndcY = p.y / p.z / tanHalf;
        screen.push_back({(ndcX + 1.0) * 0.5 * width, (1.0 - ndcY) * 0.5 * height});
    }
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    double distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < screen.size(); ++i)
        distance = std::min(distance, distanceToSegment(centre, screen[i], screen[(i + 1) % screen.size()]));
    return distance;
}

} // namespace trimlab
