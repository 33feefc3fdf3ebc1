#pragma once
/// \file
/// Unit directions spread evenly over the upper half-sphere (a Fibonacci spiral): each
/// stands for an antipodal pair ±d, for the ray-pair queries of skeleton centring and
/// evaluation.

#include <glm/vec3.hpp>

#include <vector>

namespace trimlab {

/// `count` unit vectors with z > 0, in spiral order. Empty for count < 1.
[[nodiscard]] std::vector<glm::dvec3> halfSphereDirections(int count);

} // namespace trimlab
