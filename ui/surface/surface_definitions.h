#pragma once
/// \file
/// What the Create menu and the Surface panel make surfaces from: the NURBS primitives
/// with the parameters the menu uses (unit-sized, centred at the origin, the patch facing
/// +z so the default view sees its front), labels for the built-in cages, and the
/// definition a panel edit asks for (the current control points with another density,
/// degree, level, scheme or mode). No widget; the geometry is core/surface's.

#include "ui/surface/surface_panel.h"
#include "ui/surface/surface_settings_store.h"

#include "core/surface/editable_surface.h"
#include "core/surface/surface_definition.h"

#include <glm/vec3.hpp>

#include <QString>

#include <array>
#include <span>

namespace trimlab::ui {

enum class NurbsPrimitive { Sphere, Torus, Tube, Patch };

/// In menu order.
[[nodiscard]] std::span<const NurbsPrimitive> nurbsPrimitives();
/// "Sphere", "Torus", "Tube (capped)", "Patch".
[[nodiscard]] QString nurbsPrimitiveLabel(NurbsPrimitive primitive);
/// "Sphere", "Torus", "Tube", "Patch" (object names, file-safe).
[[nodiscard]] QString nurbsPrimitiveKey(NurbsPrimitive primitive);
/// The primitive with the panel's density (and degree, for the patch): sphere of radius
/// 1, torus 1 / 0.4, capped tube of radius 0.6 and height 1.6, a 6 × 6 patch of size 2.
[[nodiscard]] SurfaceDefinition makePrimitiveDefinition(NurbsPrimitive primitive, const SurfaceChoices& choices);

/// "Cube", "Torus", "T-Shape", "Tetrahedron (Loop)", … for builtInCageNames() entries.
[[nodiscard]] QString builtInCageLabel(const QString& name);

/// `choices` with the parameters `definition` has (density, level, mode, scheme; the
/// patch degree for an open NURBS surface), so the panel shows the surface's own values.
[[nodiscard]] SurfaceChoices choicesShowing(const SurfaceDefinition& definition, SurfaceChoices choices);
/// Which panel groups apply: an open NURBS surface (both directions open, no pole) is a
/// patch, whose degree can change.
[[nodiscard]] SurfacePanel::Kind panelKind(const SurfaceDefinition& definition);
/// "Sphere — NURBS, degree 2 × 2, 9 × 5 control points; 1 152 triangles".
[[nodiscard]] QString describeSurface(const EditableSurface& surface, const QString& name);

/// The definition the panel's `choices` ask for, at `controlPoints` (#C, the history's
/// current ones): NURBS with the density (and, for a patch, the degree with uniform
/// clamped knots), subdivision with the level, mode and scheme. Throws
/// std::invalid_argument naming the problem (a degree the net is too small for, Loop on
/// a cage that is not all triangles, a wrong control point count).
[[nodiscard]] SurfaceDefinition rebuiltDefinition(const SurfaceDefinition& definition,
                                                  std::span<const glm::dvec3> controlPoints,
                                                  const SurfaceChoices& choices);

} // namespace trimlab::ui
