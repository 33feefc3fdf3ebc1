#pragma once
/// \file
/// Deterministic procedural closed meshes for demo scenes and tests. Every generator
/// returns a closed oriented 2-cycle (each undirected edge used exactly once in each
/// direction), without duplicate vertices (poles are single vertices with triangle fans,
/// seams share their vertices), counter-clockwise seen from outside when `outward` (the
/// signed volume is positive), clockwise otherwise. Computation is in double precision;
/// the results are the same on every run. Invalid parameters give an empty mesh.

#include "core/mesh/triangle_mesh.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <span>

namespace trimlab {

/// Surface of revolution about the y axis. `profile` holds meridian points (r, y) with
/// r = distance from the axis: the first and the last point lie on the axis (r = 0; they
/// become the two pole vertices), every other point has r > 0. Walking along the profile
/// in the (r, y) half-plane (r to the right, y up) the solid must lie on the LEFT (e.g.
/// from the south pole up to the north pole), which makes the surface outward. The profile
/// may cross itself (a self-crossing surface). Point i at angle φ_j = 2πj/segments is
/// (r cos φ_j, y, r sin φ_j). Triangles: 2·segments·(#profile − 2).
/// Empty mesh if #profile < 3, segments < 3, an end point has r != 0 or an inner r <= 0.
[[nodiscard]] TriangleMesh makeSurfaceOfRevolution(std::span<const glm::dvec2> profile, int segments);

/// Latitude/longitude sphere: `rings` latitude bands (>= 2), `segments` meridians (>= 3),
/// pole vertices on the ±y axis. Triangles: 2·segments·(rings − 1). Empty if radius <= 0.
[[nodiscard]] TriangleMesh makeUvSphere(const glm::dvec3& center, double radius, int rings, int segments,
                                        bool outward = true);

/// Icosahedron subdivided `subdivisions` times (0..8), vertices projected to the sphere.
/// Triangles: 20·4^subdivisions. Empty if radius <= 0 or subdivisions outside 0..8.
[[nodiscard]] TriangleMesh makeIcosphere(const glm::dvec3& center, double radius, int subdivisions,
                                         bool outward = true);

/// Tube of circular cross-section `radius` swept along a closed curve given by its samples
/// (the last sample connects back to the first; do not repeat the first). The section
/// frame is parallel-transported along the curve and its closing twist is spread evenly,
/// so the tube closes without a seam. `sides` (>= 3) vertices per section, triangles:
/// 2·sides·#curve. The tube may pass through itself where the curve comes closer than
/// 2·radius (a self-crossing surface). Empty if #curve < 3, sides < 3, radius <= 0, or
/// two consecutive samples coincide.
[[nodiscard]] TriangleMesh makeTube(std::span<const glm::dvec3> closedCurve, double radius, int sides,
                                    bool outward = true);

/// Torus around the y axis through `center`: a tube of `minorRadius` around the circle of
/// `majorRadius` in the plane y = center.y. Empty unless 0 < minorRadius < majorRadius and
/// both segment counts >= 3.
[[nodiscard]] TriangleMesh makeTorus(const glm::dvec3& center, double majorRadius, double minorRadius,
                                     int majorSegments, int minorSegments, bool outward = true);

/// Axis-aligned box [lower, upper]: 8 vertices, 12 triangles. Every face is split along
/// the diagonal from its (min, min) to its (max, max) corner in its two axes, so two boxes
/// sharing a face (a face of one lying on a face of the other) have the same two triangles
/// there, with opposite orientation: coincident fragments in exact depth ties (thesis
/// chapter 6). Empty unless lower < upper on every axis.
[[nodiscard]] TriangleMesh makeBox(const glm::dvec3& lower, const glm::dvec3& upper, bool outward = true);

} // namespace trimlab
