#pragma once
/// \file
/// The space-warp brush on an editable surface's control net (thesis 8.2): the press
/// grabs a point of the surface like the mesh brush (BrushPick: the anchor on a mesh
/// triangle); each cursor move gives the drag vector of that anchor (dragVector: in the
/// view plane, or along the grabbed triangle's normal), and every control point within
/// the brush radius of the anchor moves by falloff · strength · drag
/// (controlBrushTargets, core/design/control_brush.h; Euclidean distance, smoothing
/// ignored). The surface is re-evaluated for a live preview (ControlPreview); the
/// finished drag becomes one control edit (controlEditFrame).

#include "core/design/brush_drag.h"
#include "core/design/control_preview.h"

#include "core/deform/stroke.h"
#include "core/timeline/control_edit.h"

#include <glm/vec2.hpp>

#include <vector>

namespace trimlab::ui {

class DesignSession;

class ControlBrushDrag {
public:
    /// Starts at `pick` on the session's last frame (its surface must be at the last
    /// frame's control points). Throws std::invalid_argument for unusable settings
    /// (radius <= 0, non-finite values), as controlBrushTargets does.
    ControlBrushDrag(DesignSession& session, const DragView& view, const BrushPick& pick,
                     const deform::BrushSettings& settings);

    /// Moves the anchor for the cursor at `pixel` (device pixels) and returns the mesh
    /// positions to show (#V).
    const std::vector<glm::vec3>& moveTo(glm::dvec2 pixel, bool alongNormal);
    /// The targets of the last move (empty before the first or when nothing is in reach).
    [[nodiscard]] const std::vector<ControlPointTarget>& targets() const { return m_targets; }
    [[nodiscard]] bool moved() const { return m_drag != glm::dvec3(0.0); }
    /// How far the nearest control point is from the grabbed point, and the brush radius:
    /// a radius not beyond that distance moves nothing.
    [[nodiscard]] double nearestControlPoint() const { return m_nearest; }
    [[nodiscard]] double radius() const { return m_settings.radius; }

private:
    DesignSession& m_session;
    DragView m_view;
    BrushPick m_pick;
    deform::BrushSettings m_settings;
    glm::dvec3 m_normal{0.0};
    ControlPreview m_preview;
    std::vector<ControlPointTarget> m_targets;
    glm::dvec3 m_drag{0.0};
    double m_nearest = 0.0;
};

} // namespace trimlab::ui
