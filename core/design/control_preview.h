#pragma once
/// \file
/// The live preview of a control-point edit in progress (a drag, a brush stroke on the
/// net): moves the editable surface's control points to the edit's current targets and
/// re-evaluates only what depends on them, giving the mesh positions to show. Vertices
/// outside the moved points' supports keep the history's exact positions (bits), so under
/// the dynamic rules only the triangles the edit really moves count as moved — as they
/// will in the recorded frame (controlEditFrame).
///
/// The surface is left at the preview's control points; the owner puts it back with
/// DesignSession::syncSurface() when the edit ends (committed or not).

#include "core/timeline/control_edit.h"
#include "core/surface/editable_surface.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

class ControlPreview {
public:
    /// Starts at the surface's current control points; `positions` are the history's
    /// current mesh positions (#V), the ones the surface's mesh evaluates to.
    ControlPreview(EditableSurface& surface, std::vector<glm::vec3> positions);

    /// Moves the targets' points (any order; duplicates: the last wins) and puts every
    /// point an earlier update moved but this one does not back at its start. Returns
    /// the mesh positions to show (#V). Throws what EditableSurface::moveControlPoints
    /// throws (a broken tie, a non-finite position); the preview is unchanged then.
    const std::vector<glm::vec3>& update(std::span<const ControlPointTarget> targets);

    [[nodiscard]] const std::vector<glm::vec3>& positions() const { return m_positions; }
    /// The control points at the press (#C).
    [[nodiscard]] const std::vector<glm::dvec3>& startControlPoints() const { return m_start; }

private:
    EditableSurface& m_surface;
    std::vector<glm::dvec3> m_start;
    std::vector<glm::vec3> m_positions;
    std::vector<std::uint32_t> m_moved; ///< every index an update moved, ascending
};

} // namespace trimlab
