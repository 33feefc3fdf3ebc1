#pragma once
/// \file
/// Exact rational NURBS primitives (Piegl & Tiller ch. 7–8): surfaces of revolution about
/// the y axis through `center`, built as the tensor product of the exact rational circle
/// (degree 2, 9 control points on a square, corner weights √2/2, knots
/// {0,0,0,1,1,2,2,3,3,4,4,4}) in u with a profile curve in v, plus an open bicubic patch.
///
/// Every surface of revolution maps u to the angle φ (φ = 0 at +x, increasing from +x
/// towards −z, so u runs clockwise seen from +y) and puts profile point (r, y) at
/// center + (r cos φ, y, −r sin φ). Profiles run with the solid on their left, so Su × Sv
/// points out of the solid and the closed primitives tessellate with positive volume.
/// All returned surfaces pass requireValidNurbs. Invalid parameters (non-finite values,
/// non-positive radii or height, minor radius >= major radius, patch counts outside
/// 4..1000) throw std::invalid_argument naming the function and the parameter.

#include "core/surface/nurbs_surface.h"

#include <glm/vec3.hpp>

namespace trimlab {

/// Sphere of `radius`: u = longitude (closedU, 9 columns), v = latitude from the south
/// pole (v = 0, y = center.y − radius) to the north pole (v = 2): a rational semicircle,
/// degree 2, 5 rows, knots {0,0,0,1,1,2,2,2}. Rows 0 and 4 are poles. 9×5 control points.
[[nodiscard]] NurbsSurface makeNurbsSphere(const glm::dvec3& center, double radius);

/// Torus around the y axis: the tube circle of `minorRadius` whose centre runs on the
/// circle of `majorRadius` in the plane y = center.y. Closed in u and v, 9×9 control
/// points, degree 2×2; v = 0 at the outer equator, v increasing upwards first.
[[nodiscard]] NurbsSurface makeNurbsTorus(const glm::dvec3& center, double majorRadius, double minorRadius);

/// Open cylinder (no caps) of `radius`, from y = center.y − height/2 (v = 0) to
/// center.y + height/2 (v = 1): closedU, degree 2×1, 9×2 control points. Its tessellation
/// has two boundary loops.
[[nodiscard]] NurbsSurface makeNurbsCylinder(const glm::dvec3& center, double radius, double height);

/// Closed capped tube (a solid cylinder) as one surface: the profile is the polyline
/// bottom centre → bottom rim → top rim → top centre (degree 1 in v, 4 rows, knots
/// {0,0,1,2,3,3}: v in [0,1] is the bottom disc, [1,2] the side, [2,3] the top disc).
/// Rows 0 and 3 are poles (the cap centres); the rim circles are knots, so the
/// tessellation keeps them as sharp edges. 9×4 control points, degree 2×1.
[[nodiscard]] NurbsSurface makeNurbsCappedTube(const glm::dvec3& center, double radius, double height);

/// Open non-rational bicubic patch (degree 3×3) over a countU × countV grid of control points spread
/// uniformly over [center.x ± sizeX/2] × [center.z ± sizeZ/2] in the plane y = center.y,
/// with uniform clamped knots on [0, 1] and weights 1. u runs along +x, v along −z, so the
/// normal is +y. Its tessellation has one boundary loop.
[[nodiscard]] NurbsSurface makeNurbsPatch(const glm::dvec3& center, double sizeX, double sizeZ, int countU, int countV);

} // namespace trimlab
