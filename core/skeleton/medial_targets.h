#pragma once
/// \file
/// The medial points the contraction pulls toward (ContractionOptions::medialWeight):
/// each vertex's inward chord midpoint (skeleton_refinement.h), kept only where
/// the chord is not much longer than the surface's curvature allows. On a tube the chord
/// crosses the tube and its midpoint lies on the axis; at the cap of a limb the inward
/// normal runs along the axis, the chord crosses the whole limb and its midpoint lies
/// half a limb back — pulling the tip there would shorten the limb, the opposite of what
/// the term is for. A convex point of mean curvature H lies on an osculating sphere of
/// radius about 1/|H| (a tube's side: 2r, a cap: r), so a half-chord above
/// kMaxHalfChordCurvature / |H| runs along a limb and the vertex gets no medial point.

#include "core/mesh/triangle_mesh.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace trimlab {

/// Half-chord × |H| above which a chord midpoint is not used: 1 on a sphere, ½ on a
/// tube's side, L/(2r) at the pole of a limb of length L and radius r, 1.8 on the ring
/// next to the pole of the test capsule (its chord meets the far wall 0.8 r up the
/// axis), which 2 would keep.
inline constexpr double kMaxHalfChordCurvature = 1.5;

/// Per vertex of `mesh`: `midpoints[v]` where |midpoints[v] − x_v|·|H_v| ≤
/// kMaxHalfChordCurvature (H from the cotangent Laplacian and mixed Voronoi areas,
/// meyer_laplacian.h), none otherwise or where `midpoints[v]` is none.
/// `midpoints` holds one entry per vertex (inwardChordMidpoints).
[[nodiscard]] std::vector<std::optional<glm::dvec3>>
medialTargets(const TriangleMesh& mesh, const std::vector<std::optional<glm::dvec3>>& midpoints);

} // namespace trimlab
