#pragma once
/// \file
/// Comparing a GPU pass's results, read back with GpuScene::readPositions/readNormals, with
/// the CPU's: the largest distance between two sets of xyz vectors (render.gpu_skinning,
/// render.gpu_subdivision).

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab::test {

/// max over i of |a[i] − b[i]| (the sizes must match), in double precision.
[[nodiscard]] double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b);
[[nodiscard]] double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::dvec3>& b);

} // namespace trimlab::test
