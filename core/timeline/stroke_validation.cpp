#include "core/timeline/stroke_validation.h"

#include <cmath>

namespace trimlab::timeline {

namespace {

bool isFinite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

std::string strokeProblem(const deform::Stroke& stroke)
{
    const deform::BrushSettings& brush = stroke.brush;
    if (!isFinite(stroke.anchor))
        return "the anchor is not finite";
    if (!isFinite(stroke.drag))
        return "the drag is not finite";
    if (!(std::isfinite(brush.radius) && brush.radius > 0.0))
        return "the radius must be finite and > 0";
    if (!std::isfinite(brush.strength))
        return "the strength is not finite";
    if (!(brush.smoothingStep > 0.0 && brush.smoothingStep <= 1.0))
        return "the smoothing step must be in (0, 1]";
    if (brush.smoothingIterations < 0 || brush.smoothingIterations > kMaxSmoothingIterations)
        return "the smoothing iterations must be in [0, " + std::to_string(kMaxSmoothingIterations) + "]";
    return {};
}

} // namespace trimlab::timeline
