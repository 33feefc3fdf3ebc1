#pragma once
/// \file
/// The angle term of the warp (thesis 8.2: "an angle-weighted estimation process computes
/// the attenuated deformation at each vertex"): how much of its falloff-weighted pull a
/// vertex receives given how its normal faces the drag, relative to the anchor.

#include <glm/vec3.hpp>

namespace trimlab::deform {

/// a_v = min(1, 1 + (n_v − n_a)·ĝ / 2) in [0, 1], with n_v the vertex normal at drag
/// start, n_a the surface normal at the anchor and ĝ the unit drag direction (unit
/// vectors; a zero normal reads as "no preference").
///
/// Why this form: n·ĝ says how much a surface element faces the drag (1 facing it, 0
/// side-on, −1 facing away), and the deficit (n_a − n_v)·ĝ ∈ [−2, 2] how much less the
/// vertex faces it than the grabbed spot. A vertex with no deficit, the anchor itself
/// included, moves fully (a = 1), so the grabbed spot always follows the cursor like a
/// magnet and a flat region moves rigidly. A deficit is mapped linearly onto the lost
/// fraction of the pull, with the largest possible deficit (2: the anchor faces the drag
/// head-on, the vertex faces exactly away) losing all of it. Pulling a bump out of a
/// surface (ĝ = n_a) then moves a side-on vertex half and holds the back of a thin fin
/// still instead of dragging it through the grabbed sheet; pushing straight in (ĝ = −n_a)
/// attenuates nothing, so the dent moves as one.
/// The linear form is Lipschitz in the normals everywhere. The ratio
/// (1 + n_v·ĝ)/(1 + n_a·ĝ), which also gives a = 1 at the anchor, was rejected: when
/// pushing almost straight in its denominator nears 0, and normals a degree apart around
/// the anchor would get attenuations anywhere between 0 and 1 (a ragged dent).
/// Returns 1 when `dragDirection` is zero (there is no displacement to attenuate).
[[nodiscard]] double angleAttenuation(const glm::dvec3& vertexNormal, const glm::dvec3& anchorNormal,
                                      const glm::dvec3& dragDirection);

} // namespace trimlab::deform
