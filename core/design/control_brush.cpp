#include "core/design/control_brush.h"

#include "core/deform/falloff.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

bool isFinite(const glm::dvec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// The brush's distance: Euclidean, summed in x, y, z order.
double distanceBetween(const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 d = a - b;
    return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

// The selection, sorted and unique, checked against #C.
std::vector<std::uint32_t> checkedSelection(const EditableSurface& surface, std::span<const std::uint32_t> selection,
                                            const char* caller)
{
    std::vector<std::uint32_t> sorted(selection.begin(), selection.end());
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (!sorted.empty() && sorted.back() >= surface.controlPointCount())
        throw std::invalid_argument(std::string(caller) + ": control point " + std::to_string(sorted.back()) +
                                    " does not exist (the surface has " + std::to_string(surface.controlPointCount()) +
                                    ")");
    return sorted;
}

// The selection and every point tied to it, each moved by `offset`.
std::vector<ControlPointTarget> offsetTargets(const EditableSurface& surface,
                                              const std::vector<std::uint32_t>& selection, const glm::dvec3& offset)
{
    std::vector<std::uint32_t> moved;
    for (const std::uint32_t c : selection)
        for (const std::uint32_t t : surface.tiedPoints(c))
            moved.push_back(t);
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    std::vector<ControlPointTarget> targets;
    for (const std::uint32_t c : moved)
        targets.push_back({c, surface.controlPoints()[c] + offset});
    return targets;
}

} // namespace

std::vector<ControlPointTarget> controlBrushTargets(std::span<const glm::dvec3> controlPoints, const glm::dvec3& anchor,
                                                    const glm::dvec3& drag, const deform::BrushSettings& brush)
{
    if (!isFinite(anchor) || !isFinite(drag))
        throw std::invalid_argument("controlBrushTargets: the anchor and the drag must be finite");
    if (!std::isfinite(brush.radius) || !(brush.radius > 0.0))
        throw std::invalid_argument("controlBrushTargets: the brush radius must be finite and > 0");
    if (!std::isfinite(brush.strength))
        throw std::invalid_argument("controlBrushTargets: the brush strength must be finite");
    std::vector<ControlPointTarget> targets;
    for (std::size_t c = 0; c < controlPoints.size(); ++c) {
        const double distance = distanceBetween(controlPoints[c], anchor);
        const double weight = deform::falloff(brush.profile, distance / brush.radius) * brush.strength;
        const glm::dvec3 offset = weight * drag;
        if (weight == 0.0 || (offset.x == 0.0 && offset.y == 0.0 && offset.z == 0.0))
            continue;
        targets.push_back({std::uint32_t(c), controlPoints[c] + offset});
    }
    return targets;
}

double nearestControlPointDistance(std::span<const glm::dvec3> controlPoints, const glm::dvec3& anchor)
{
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& p : controlPoints)
        nearest = std::min(nearest, distanceBetween(p, anchor));
    return nearest;
}

std::vector<ControlPointTarget> translateControlPoints(const EditableSurface& surface,
                                                       std::span<const std::uint32_t> selection, const glm::dvec3& drag)
{
    if (!isFinite(drag))
        throw std::invalid_argument("translateControlPoints: the drag must be finite");
    return offsetTargets(surface, checkedSelection(surface, selection, "translateControlPoints"), drag);
}

std::vector<ControlPointTarget> moveControlPointsAlongNormal(const EditableSurface& surface,
                                                             std::span<const std::uint32_t> selection, double distance)
{
    if (!std::isfinite(distance))
        throw std::invalid_argument("moveControlPointsAlongNormal: the distance must be finite");
    const std::vector<std::uint32_t> sorted = checkedSelection(surface, selection, "moveControlPointsAlongNormal");
    glm::dvec3 sum(0.0);
    for (const std::uint32_t c : sorted)
        sum += surface.controlPointNormal(c);
    const double length = std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
    if (!(length > 1e-12))
        return {};
    return offsetTargets(surface, sorted, sum / length * distance);
}

} // namespace trimlab
