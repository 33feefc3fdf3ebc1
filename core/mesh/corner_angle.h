#pragma once
/// \file
/// The interior angle of a triangle corner, the weight of angle-weighted vertex normals.
/// One definition, so that normals recomputed on a brush region agree to the bit with
/// normals of the whole mesh.

#include <glm/vec3.hpp>

namespace trimlab {

/// Interior angle (radians) at `a` of triangle (a, b, c); 0 for degenerate corners.
[[nodiscard]] double cornerAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

} // namespace trimlab
