#include "core/trim/clip_set.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace trimlab {

namespace {

/// What one enabled plane does to [zNear, zFar]: nothing, everything, or a bound.
struct PlaneBound {
    enum Kind { KeepsAll, KeepsNothing, Lower, Upper } kind = KeepsAll;
    double t = 0.0;
};

// The arithmetic of keptSpan(ClipPlane) exactly, so a one-plane set matches it bit for bit.
PlaneBound planeBound(const ClipPlane& plane, const PixelRay& ray, double zNear, double zFar)
{
    const double f0 = plane.evaluate(ray.origin);
    const double slope = glm::dot(plane.normal, ray.direction);
    const double fNear = f0 + slope * zNear;
    const double fFar = f0 + slope * zFar;
    if (fNear >= 0.0 && fFar >= 0.0)
        return {};
    if (fNear < 0.0 && fFar < 0.0)
        return {PlaneBound::KeepsNothing, 0.0};
    const double t = std::clamp(-f0 / slope, zNear, zFar);
    return {fNear >= 0.0 ? PlaneBound::Upper : PlaneBound::Lower, t};
}

/// Keeps the largest (lower bounds) or smallest (upper bounds) plane bound and the
/// runner-up plane bound (±infinity while there is none).
struct BoundTracker {
    double best;
    double runnerUp;
    int plane = -1;

    // A plane's bound is clamped to [zNear, zFar], so the first plane always takes over
    // from the near/far default (also when clamped onto it, as keptSpan(ClipPlane) does).
    void offerLower(double t, int index)
    {
        if (plane < 0 || t > best) {
            if (plane >= 0)
                runnerUp = best;
            best = t;
            plane = index;
        } else {
            runnerUp = std::max(runnerUp, t);
        }
    }
    void offerUpper(double t, int index)
    {
        if (plane < 0 || t < best) {
            if (plane >= 0)
                runnerUp = best;
            best = t;
            plane = index;
        } else {
            runnerUp = std::min(runnerUp, t);
        }
    }
};

constexpr double kInfinity = std::numeric_limits<double>::infinity();

} // namespace

int ClipSet::enabledCount() const
{
    return int(std::count_if(planes.begin(), planes.end(), [](const ClipPlane& p) { return p.enabled; }));
}

bool ClipSet::keeps(const glm::dvec3& p) const
{
    return std::all_of(planes.begin(), planes.end(),
                       [&](const ClipPlane& plane) { return !plane.enabled || plane.evaluate(p) >= 0.0; });
}

ClipSet ClipSet::box(const glm::dvec3& lower, const glm::dvec3& upper)
{
    ClipSet set;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 n(0.0);
        n[axis] = 1.0;
        set.planes[std::size_t(2 * axis)] = ClipPlane{true, n, -lower[axis]};
        set.planes[std::size_t(2 * axis + 1)] = ClipPlane{true, -n, upper[axis]};
    }
    return set;
}

ClipSet ClipSet::single(const ClipPlane& plane)
{
    ClipSet set;
    set.planes[0] = plane;
    return set;
}

KeptSpan keptSpan(const ClipSet& clips, const PixelRay& ray, double zNear, double zFar)
{
    BoundTracker start{zNear, -kInfinity};
    BoundTracker end{zFar, kInfinity};
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        const ClipPlane& plane = clips.planes[std::size_t(i)];
        if (!plane.enabled)
            continue;
        const PlaneBound bound = planeBound(plane, ray, zNear, zFar);
        if (bound.kind == PlaneBound::KeepsNothing)
            return {true, 0.0, 0.0, true};
        if (bound.kind == PlaneBound::Lower)
            start.offerLower(bound.t, i);
        else if (bound.kind == PlaneBound::Upper)
            end.offerUpper(bound.t, i);
    }
    if (start.best > end.best)
        return {true, 0.0, 0.0, true};
    return {false, start.best, end.best, start.plane < 0, start.plane, end.plane, start.runnerUp, end.runnerUp};
}

std::optional<ClipSet> parseClipSet(const std::vector<std::string>& texts, std::string* error)
{
    if (texts.size() > std::size_t(kMaxClipPlanes)) {
        if (error)
            *error =
                "at most " + std::to_string(kMaxClipPlanes) + " clipping planes, got " + std::to_string(texts.size());
        return std::nullopt;
    }
    ClipSet set;
    for (std::size_t i = 0; i < texts.size(); ++i) {
        std::string planeError;
        const std::optional<ClipPlane> plane = parseClipPlane(texts[i], &planeError);
        if (!plane) {
            if (error)
                *error = "plane " + std::to_string(i + 1) + ": " + planeError;
            return std::nullopt;
        }
        set.planes[i] = *plane;
    }
    return set;
}

} // namespace trimlab
