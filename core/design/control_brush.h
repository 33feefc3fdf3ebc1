#pragma once
/// \file
/// Ways to move control points that the UI turns into control edits (control_edit.h):
/// the space-warp brush applied to control points (thesis 8.2's magnet-like linear space
/// warp, acting on the net instead of the mesh), a drag of selected points in the view
/// plane, and a move along their normal. All return targets (index, new position) for
/// controlEditFrame; none changes anything.

#include "core/deform/stroke.h"
#include "core/timeline/control_edit.h"
#include "core/surface/editable_surface.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// The space-warp brush on control points: every control point p within
/// `brush.radius` of `anchor` (Euclidean distance d = |p − anchor|) moves by
/// falloff(brush.profile, d / radius) · brush.strength · drag (deform/falloff.h).
/// The distance is Euclidean, not geodesic as for the mesh brush: control points lie
/// off the surface and the net is not a surface one could measure along (a NURBS net's
/// polygon may cross itself, a cage is coarse), so "near the grabbed point" means near
/// in space. Smoothing settings of `brush` are ignored (the surface is smooth already).
/// Tied NURBS points get one target each (they are equally far, so move equally).
/// Points whose displacement is exactly zero are left out; the result is sorted by index.
/// Throws std::invalid_argument for non-finite anchor/drag, radius <= 0 or non-finite,
/// or non-finite strength.
[[nodiscard]] std::vector<ControlPointTarget> controlBrushTargets(std::span<const glm::dvec3> controlPoints,
                                                                  const glm::dvec3& anchor, const glm::dvec3& drag,
                                                                  const deform::BrushSettings& brush);

/// The Euclidean distance from `anchor` to the nearest of `controlPoints` (infinity when
/// there are none): a brush whose radius does not exceed it moves no control point, which
/// the designer must be told rather than see nothing happen.
[[nodiscard]] double nearestControlPointDistance(std::span<const glm::dvec3> controlPoints, const glm::dvec3& anchor);

/// Moves the selected control points rigidly by `drag` (e.g. the mouse drag unprojected
/// into the view plane through the selection's centroid: the UI computes that vector
/// from its camera). Tied points follow. Duplicate indices are ignored. Throws
/// std::invalid_argument for an index >= #C or a non-finite drag.
[[nodiscard]] std::vector<ControlPointTarget> translateControlPoints(const EditableSurface& surface,
                                                                     std::span<const std::uint32_t> selection,
                                                                     const glm::dvec3& drag);

/// Moves the selected control points by `distance` (object units; > 0 outward) along
/// their average normal: the normalised sum of controlPointNormal() of the selection.
/// All points move by the same vector (the selection keeps its shape). When that average
/// vanishes (e.g. opposite points selected) nothing moves: empty result. Same throws as
/// translateControlPoints (non-finite distance).
[[nodiscard]] std::vector<ControlPointTarget>
moveControlPointsAlongNormal(const EditableSurface& surface, std::span<const std::uint32_t> selection, double distance);

} // namespace trimlab
