#pragma once
/// \file
/// Reading a GPU pass's results back for comparison with the CPU: xyz vectors from a shader
/// storage buffer (the scene's positions or normals) and the largest distance between two
/// sets of them (render.gpu_skinning, render.gpu_subdivision).

#include "render/gl/gl_functions.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab::test {

/// `count` tightly packed float xyz vectors of `buffer` from vector `first` on.
[[nodiscard]] std::vector<glm::vec3> readVec3(render::GlFunctions& gl, GLuint buffer, std::size_t first,
                                              std::size_t count);

/// max over i of |a[i] − b[i]| (the sizes must match), in double precision.
[[nodiscard]] double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b);
[[nodiscard]] double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::dvec3>& b);

} // namespace trimlab::test
