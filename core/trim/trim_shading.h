#pragma once
/// \file
/// How a shown trim point is colored. The GLSL twin is shaders/common/trim_shading.glsl;
/// keep the two identical (render tests compare colors against the CPU reference).

#include "core/trim/inspect_settings.h"

#include <glm/vec3.hpp>

namespace trimlab {

/// Front-facing surface: warm yellow; back-facing (the inside seen through a cut or a
/// trimmed hole): blue — the convention of the thesis figures (Fig. 8.11).
inline constexpr glm::vec3 kFrontFacingColor{0.96f, 0.78f, 0.26f};
inline constexpr glm::vec3 kBackFacingColor{0.28f, 0.50f, 0.96f};
inline constexpr glm::vec3 kBackgroundColor{0.16f, 0.17f, 0.20f};
/// The back face of an object a CSG expression subtracts (csgSubtractedMask): the wall
/// the difference carved, teal, so that it is not taken for an inside seen through a cut.
inline constexpr glm::vec3 kCarvedWallColor{0.24f, 0.70f, 0.62f};
inline constexpr float kAmbient = 0.25f;

/// Caps are drawn in the front-facing color (the object's color: the cut shows the solid
/// as if sawn through) with the pattern's lines darkened to this fraction.
inline constexpr float kCapLineShade = 0.45f;
/// Collision tint (thesis Figs. 6.8 right, 7.4c: red) and how strongly it replaces the shading.
inline constexpr glm::vec3 kCollisionColor{0.95f, 0.10f, 0.08f};
inline constexpr float kCollisionTint = 0.65f;

/// Headlight Lambert shading. `normal`: unit surface normal (any orientation);
/// `toViewer`: unit vector from the point to the eye; `facing`: +1 or −1.
[[nodiscard]] glm::vec3 shadeTrimPoint(int facing, const glm::dvec3& normal, const glm::dvec3& toViewer);
/// shadeTrimPoint of a back face, with `carved`: in kCarvedWallColor (a wall a CSG
/// difference carved) instead of the back-facing blue.
[[nodiscard]] glm::vec3 shadeTrimPoint(int facing, const glm::dvec3& normal, const glm::dvec3& toViewer, bool carved);

/// An orthonormal basis (u, v) of the plane with unit normal `n`, chosen from n alone (so
/// a cap's pattern is fixed in world space): u = normalize(cross(n, a)) with a the world
/// axis least aligned with n (the first of x, y, z on ties), v = cross(n, u).
void capPatternBasis(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v);

/// 1 on a line of the cap pattern at world point `p` of the plane with unit normal `n`,
/// else 0 (Solid, or spacing <= 0: always 0). Striped: lines where
/// fract(dot(p, u) / spacing) < lineWidth; Hatched: the same along (u + v)/√2 and (u − v)/√2.
[[nodiscard]] bool onCapLine(const CapSettings& cap, const glm::dvec3& p, const glm::dvec3& n);

/// A cap at world point `p` of the plane with unit normal `n`: flat Lambert shading
/// (headlight, two-sided) of the front-facing color, darkened on the pattern's lines.
[[nodiscard]] glm::vec3 shadeCap(const CapSettings& cap, const glm::dvec3& p, const glm::dvec3& n,
                                 const glm::dvec3& toViewer);

/// Color of a coplanar group of `count` fragments (thesis Fig. 6.9): 2 red, 3 blue,
/// 4 green, 5 cyan, 6 aquamarine, 7 fuchsia, 8 yellow, 9 or more brown. `count` < 2 has
/// no color (returns the input `shaded`).
[[nodiscard]] glm::vec3 coplanarColor(int count, const glm::vec3& shaded);

/// The shaded color of a shown fragment with the highlights applied: a coplanar group
/// (count >= 2) takes its palette color lit like `shaded`; a collision is tinted red.
[[nodiscard]] glm::vec3 applyHighlights(const glm::vec3& shaded, float lighting, bool collision, int coplanarCount);

} // namespace trimlab
