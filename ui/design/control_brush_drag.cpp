#include "ui/design/control_brush_drag.h"

#include "ui/design/design_session.h"

#include "core/design/control_brush.h"

#include <glm/geometric.hpp>

namespace trimlab::ui {

namespace {

/// Unit normal of `triangle` at `positions`; (0,0,0) for a degenerate one (a Shift drag
/// then moves nothing rather than producing NaN).
glm::dvec3 triangleNormal(const std::vector<glm::vec3>& positions, const glm::uvec3& t)
{
    const glm::dvec3 a(positions[t.x]);
    const glm::dvec3 n = glm::cross(glm::dvec3(positions[t.y]) - a, glm::dvec3(positions[t.z]) - a);
    const double length = glm::length(n);
    return length > 0.0 ? n / length : glm::dvec3(0.0);
}

} // namespace

ControlBrushDrag::ControlBrushDrag(DesignSession& session, const DragView& view, const BrushPick& pick,
                                   const deform::BrushSettings& settings)
    : m_session(session),
      m_view(view),
      m_pick(pick),
      m_settings(settings),
      m_normal(
          triangleNormal(session.timeline().currentPositions(), session.timeline().base().triangles.at(pick.triangle))),
      m_preview(*session.surface(), session.timeline().currentPositions()),
      m_nearest(nearestControlPointDistance(m_preview.startControlPoints(), pick.anchor))
{
    // Checks the settings now, so that a bad radius is refused at the press.
    (void)controlBrushTargets({}, pick.anchor, glm::dvec3(0.0), settings);
}

const std::vector<glm::vec3>& ControlBrushDrag::moveTo(glm::dvec2 pixel, bool alongNormal)
{
    m_drag = dragVector(m_view, m_pick, pixel, alongNormal, m_normal, m_session.modelMatrix());
    std::vector<ControlPointTarget> targets =
        controlBrushTargets(m_preview.startControlPoints(), m_pick.anchor, m_drag, m_settings);
    const std::vector<glm::vec3>& positions = m_preview.update(targets);
    m_targets = std::move(targets);
    return positions;
}

} // namespace trimlab::ui
