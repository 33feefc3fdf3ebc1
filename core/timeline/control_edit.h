#pragma once
/// \file
/// Control-point edits as timeline frames (thesis 8.2 with 8.1.1–8.1.2): moving control
/// points of an editable surface re-evaluates its fixed-connectivity mesh; the frame
/// stores the moved control points and exactly the mesh vertices whose float bits
/// changed, so the dynamic rules' "did this primitive move" works as for brush strokes,
/// and undo (Timeline::removeLastFrame) restores both bit for bit.
///
/// The usual sequence (the UI's undo command does this):
///
///     EditableSurface surface(*timeline.surface());                  // once
///     surface.setControlPoints(timeline.currentControlPoints());     // mirror the last frame
///     Frame f = controlEditFrame(surface, targets, timeline.currentPositions());
///     timeline.appendFrame(f);                                       // redo: the same
///     ...
///     timeline.removeLastFrame();                                    // undo
///     surface.setControlPoints(timeline.currentControlPoints());

#include "core/surface/editable_surface.h"
#include "core/timeline/timeline.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Where an edit wants control point `index` to be (object space).
struct ControlPointTarget {
    std::uint32_t index = 0;
    glm::dvec3 position{0.0};
    friend bool operator==(const ControlPointTarget&, const ControlPointTarget&) = default;
};

/// A new history for the editable surface `definition`: base mesh = its tessellation at
/// its own control points, one empty set of `firstRule`. Throws like EditableSurface's
/// constructor.
[[nodiscard]] timeline::Timeline surfaceTimeline(const SurfaceDefinition& definition,
                                                 DynamicRule firstRule = DynamicRule::Confluent);

/// Throws std::invalid_argument unless `history` has a surface equal to
/// `surface.definition()` and a base mesh with the same vertex count and triangles as the
/// surface's tessellation (what a loaded project must satisfy before editing goes on).
/// The message says which part disagrees.
void requireSurfaceMatchesTimeline(const EditableSurface& surface, const timeline::Timeline& history);

/// The control edit that moves the targets, as a frame ready for Timeline::appendFrame.
/// - `surface` must be at the history's current control points (its controlPoints() are
///   the moves' 'before'); on success it is left at the edited control points (what the
///   view shows next); on a throw it is unchanged.
/// - `targets`: any order. Each target moves its tied points too (NURBS seam twins and
///   poles, tiedControlPoints). Targets whose position equals the current one (bits) are
///   dropped.
/// - `positionsBefore`: the history's current mesh positions (#V; Timeline::
///   currentPositions()). The frame lists exactly the vertices, inside the supports of
///   the moved control points, whose float bits differ from `positionsBefore` after
///   re-evaluation, with their exact 'before' (from `positionsBefore`) and 'after'.
/// Throws std::invalid_argument naming the problem: no targets left after dropping
/// ("nothing moves"), an index >= #C, a non-finite position, two targets that give one
/// point (directly or through a tie) different positions, or positionsBefore of the
/// wrong size.
[[nodiscard]] timeline::Frame controlEditFrame(EditableSurface& surface, std::span<const ControlPointTarget> targets,
                                               std::span<const glm::vec3> positionsBefore);

/// controlEditFrame on the history's current state, then Timeline::appendFrame. Sets the
/// surface to the history's current control points first if it is not there. Returns the
/// appended frame. Throws what they throw (the history unchanged then).
timeline::Frame appendControlEdit(timeline::Timeline& history, EditableSurface& surface,
                                  std::span<const ControlPointTarget> targets);

} // namespace trimlab
