#include "core/trim/clip_plane.h"

#include "core/util/parse_numbers.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace trimlab {

KeptSpan keptSpan(const ClipPlane& plane, const PixelRay& ray, double zNear, double zFar)
{
    KeptSpan span{false, zNear, zFar, true};
    if (!plane.enabled)
        return span;
    // f(t) = n·(o + t d) + offset is linear in t.
    const double f0 = plane.evaluate(ray.origin);
    const double slope = glm::dot(plane.normal, ray.direction);
    const double fNear = f0 + slope * zNear;
    const double fFar = f0 + slope * zFar;
    if (fNear >= 0.0 && fFar >= 0.0)
        return span;
    if (fNear < 0.0 && fFar < 0.0)
        return {true, 0.0, 0.0, true};
    const double tPlane = -f0 / slope;
    if (fNear >= 0.0) {
        span.tEnd = std::clamp(tPlane, zNear, zFar);
        span.endPlane = 0;
    } else {
        span.tStart = std::clamp(tPlane, zNear, zFar);
        span.startsAtNear = false;
        span.startPlane = 0;
    }
    return span;
}

std::optional<ClipPlane> parseClipPlane(std::string_view text, std::string* error)
{
    const std::optional<std::vector<double>> v = parseNumberList(text, 4, error);
    if (!v)
        return std::nullopt;
    ClipPlane plane{true, {(*v)[0], (*v)[1], (*v)[2]}, (*v)[3]};
    if (glm::length(plane.normal) == 0.0) {
        if (error)
            *error = "clip plane normal (a,b,c) must not be zero";
        return std::nullopt;
    }
    return plane;
}

} // namespace trimlab
