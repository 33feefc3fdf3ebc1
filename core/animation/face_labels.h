#pragma once
/// \file
/// Per-face labels from per-vertex labels, for displays and exports that colour faces.

#include "core/animation/vertex_graph.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// #F labels: the label two or three corners share; when all three corners differ (a
/// face where three segments meet), the label of the first corner.
[[nodiscard]] std::vector<std::uint32_t> faceLabels(std::span<const glm::uvec3> triangles,
                                                    const VertexLabeling& labeling);

} // namespace trimlab
