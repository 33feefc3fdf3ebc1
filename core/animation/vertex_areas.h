#pragma once
/// \file
/// Barycentric vertex areas: the area measure a(·) of segments and clusters.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// #V areas: a third of the area of every triangle a vertex belongs to (0.5·|(b−a)×(c−a)|
/// per triangle, in the positions' squared units). They sum to the surface area, so the
/// area of a vertex segment is Σ over its vertices, and triangles that straddle two
/// segments are shared between them instead of belonging to neither (thesis 3.1.2 sums
/// the facets of a segment; with vertex segments that would drop the border triangles).
/// Degenerate triangles add 0. Indices must be < positions.size().
[[nodiscard]] std::vector<double> vertexAreas(std::span<const glm::vec3> positions,
                                              std::span<const glm::uvec3> triangles);

/// Σ areas[v] per label: #labels sums for `labels` in [0, count).
[[nodiscard]] std::vector<double> labelAreas(std::span<const std::uint32_t> labels, std::size_t count,
                                             std::span<const double> areas);

} // namespace trimlab
