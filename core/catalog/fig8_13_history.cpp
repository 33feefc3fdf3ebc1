#include "core/catalog/fig8_13_history.h"

#include "core/timeline/control_edit.h"
#include "core/surface/nurbs_primitives.h"
#include "core/surface/subdivision_cages.h"

#include <vector>

namespace trimlab {

namespace {

// Row j of the net as targets moved by `offset`, for the points whose x exceeds `minX`.
std::vector<ControlPointTarget> rowTargets(const NurbsSurface& net, const std::vector<glm::dvec3>& points, int j,
                                           double minX, const glm::dvec3& offset)
{
    std::vector<ControlPointTarget> targets;
    for (int i = 0; i < net.countU; ++i) {
        const std::size_t c = net.index(i, j);
        if (points[c].x > minX)
            targets.push_back({std::uint32_t(c), points[c] + offset});
    }
    return targets;
}

} // namespace

timeline::Timeline fig8_13NurbsHistory(DynamicRule firstRule, DynamicRule secondRule)
{
    const NurbsSurface sphere = makeNurbsSphere(glm::dvec3(0.0), 1.0);
    const SurfaceDefinition definition = nurbsDefinition(sphere);
    timeline::Timeline history = surfaceTimeline(definition, firstRule);
    EditableSurface surface(definition);

    // Set 0: a disjoint bump, the +x side of the equator (row 2) pulled outwards.
    const std::vector<ControlPointTarget> bump =
        rowTargets(sphere, surface.controlPoints(), 2, 0.5, glm::dvec3(0.45, 0.0, 0.0));
    appendControlEdit(history, surface, bump);

    // Set 1: the north pole (row 4, its nine tied points follow index 4·9) pushed down
    // in three edits, through the sphere and out below the south pole (y = −1).
    history.startSet(secondRule);
    const auto pole = std::uint32_t(sphere.index(0, sphere.countV - 1));
    for (const double y : {0.2, -0.8, -1.7}) {
        const ControlPointTarget push{pole, glm::dvec3(0.0, y, 0.0)};
        appendControlEdit(history, surface, std::span(&push, 1));
    }
    return history;
}

timeline::Timeline subdivisionPushHistory(DynamicRule rule)
{
    const SurfaceDefinition definition =
        subdivisionDefinition(cubeCage(0.8), SubdivisionSettings{3, SubdivisionMode::Limit});
    timeline::Timeline history = surfaceTimeline(definition, rule);
    EditableSurface surface(definition);
    // The cage corner (+0.8, +0.8, +0.8) pushed down through the body and out below.
    std::uint32_t corner = 0;
    for (std::uint32_t c = 0; c < surface.controlPointCount(); ++c) {
        const glm::dvec3& p = surface.controlPoints()[c];
        if (p.x > 0.0 && p.y > 0.0 && p.z > 0.0)
            corner = c;
    }
    const ControlPointTarget push{corner, glm::dvec3(0.0, -1.2, 0.0)};
    appendControlEdit(history, surface, std::span(&push, 1));
    return history;
}

} // namespace trimlab
