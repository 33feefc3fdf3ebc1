#pragma once
/// \file
/// Angle-weighted vertex normals recomputed for a few vertices only: after a stroke the
/// UI refreshes the normals its region can have changed instead of the whole mesh (thesis
/// 8.2's "weighted vertex normal recomputation" step).

#include "core/deform/brush_topology.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab::deform {

/// Angle-weighted normals of `vertices` (one unit vec3 per entry, zero for a vertex with
/// no non-degenerate triangle), computed with the same arithmetic in the same order as
/// vertexNormals(mesh) in mesh/triangle_mesh.h, so the values are bit-identical to a full
/// recomputation. `positions` holds #V points; vertices must be < #V
/// (std::invalid_argument otherwise). Cost: the incident triangles of `vertices`.
[[nodiscard]] std::vector<glm::vec3> vertexNormalsOf(const BrushTopology& topology,
                                                     std::span<const glm::vec3> positions,
                                                     std::span<const std::uint32_t> vertices);

/// The vertices whose normal can change when the vertices `moved` move: `moved` and their
/// one-rings, sorted ascending, without duplicates. `moved` need not be sorted.
[[nodiscard]] std::vector<std::uint32_t> normalsAffectedBy(const BrushTopology& topology,
                                                           std::span<const std::uint32_t> moved);

/// Rewrites normals[v] (#V entries) for every v in `vertices` from `positions`, as
/// vertexNormalsOf computes them. For a drag in progress, compute
/// normalsAffectedBy(topology, stroke.region().vertices) once when the drag starts and
/// pass it here on every update. Throws std::invalid_argument when `positions` or
/// `normals` do not hold #V entries or a vertex is out of range.
void recomputeNormals(const BrushTopology& topology, std::span<const glm::vec3> positions,
                      std::span<const std::uint32_t> vertices, std::span<glm::vec3> normals);

/// Brings `normals` (#V, e.g. from vertexNormals(mesh) before the stroke) up to date
/// after the vertices `moved` (e.g. BrushStroke::region().vertices, or what applyStroke
/// returned) took their new `positions`: rewrites exactly the entries of
/// normalsAffectedBy(topology, moved) and returns that list, so the caller can upload
/// just those to the normal buffer. Throws std::invalid_argument when `positions` or
/// `normals` do not hold #V entries.
std::vector<std::uint32_t> updateRegionNormals(const BrushTopology& topology, std::span<const glm::vec3> positions,
                                               std::span<const std::uint32_t> moved, std::span<glm::vec3> normals);

} // namespace trimlab::deform
