#pragma once
/// \file
/// Directions spread evenly over the sphere, for tests and benchmarks that look at a scene
/// from many sides.

#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace trimlab::test {

/// Direction `i` of `count` on the Fibonacci spiral (unit length; the first near +y).
inline glm::dvec3 fibonacciDirection(int i, int count)
{
    const double y = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(1.0 - y * y);
    const double phi = i * glm::pi<double>() * (3.0 - std::sqrt(5.0));
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

} // namespace trimlab::test
