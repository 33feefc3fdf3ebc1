#pragma once
/// \file
/// Built-in closed cages for "Create > Subdivision from cage" and for tests. All are
/// closed, manifold and oriented with faces counter-clockwise seen from outside.

#include "core/surface/subdivision_cage.h"

#include <string>
#include <vector>

namespace trimlab {

/// The cube [-h, h]³ as 6 quads, 8 vertices (Catmull–Clark).
[[nodiscard]] SubdivisionCage cubeCage(double halfSize = 1.0);

/// A torus around the z axis: `ringSegments` × `tubeSegments` quads (each ≥ 3), major
/// radius `majorRadius`, tube radius `minorRadius` (< majorRadius), Catmull–Clark.
/// Throws std::invalid_argument for segment counts < 3 or radii that are not
/// 0 < minorRadius < majorRadius.
[[nodiscard]] SubdivisionCage torusCage(int ringSegments = 16, int tubeSegments = 8, double majorRadius = 1.0,
                                        double minorRadius = 0.35);

/// A "T" made of 5 unit cubes (a bar of 3 along x on top of a stem of 2 along -y), as
/// one closed quad cage of 22 quads; Catmull–Clark. Has valence-3 and valence-5 vertices.
[[nodiscard]] SubdivisionCage tShapeCage();

/// The regular tetrahedron (4 triangles), scheme Loop.
[[nodiscard]] SubdivisionCage tetrahedronCage();

/// The octahedron with vertices at ±1 on the axes (8 triangles), scheme Loop.
[[nodiscard]] SubdivisionCage octahedronCage();

/// Names of the built-in cages, for menus: "cube", "torus", "t-shape", "tetrahedron",
/// "octahedron".
[[nodiscard]] std::vector<std::string> builtInCageNames();

/// The built-in cage `name` (one of builtInCageNames(), default parameters); throws
/// std::invalid_argument naming the valid names otherwise.
[[nodiscard]] SubdivisionCage builtInCage(const std::string& name);

} // namespace trimlab
