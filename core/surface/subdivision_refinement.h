#pragma once
/// \file
/// Internal to subdivision_surface.cpp: the OpenSubdiv side of building a
/// SubdivisionSurface (topology refinement, stencil tables, ptex locations). Kept apart so
/// that only these sources include OpenSubdiv headers.

#include "core/surface/subdivision_cage.h"
#include "core/surface/subdivision_surface.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

/// Everything a SubdivisionSurface keeps from the build: stencils over cage vertices and
/// the fixed output triangles.
struct SubdivisionTables {
    std::size_t outputVertexCount = 0;
    SubdivisionSurface::StencilRows position;
    SubdivisionSurface::StencilRows tangentU; ///< limit mode only
    SubdivisionSurface::StencilRows tangentV; ///< limit mode only
    std::vector<LimitLocation> locations;     ///< limit mode only
    std::vector<glm::uvec3> triangles;
};

/// Appends `row` to `rows` sorted by cage vertex, repeated vertices merged and exact zeros
/// dropped (a zero weight must not put an output vertex into a support). Reorders `row`.
void appendStencilRow(SubdivisionSurface::StencilRows& rows, std::vector<StencilWeight>& row);

/// Output triangles the settings would produce for a valid cage (before any refinement).
[[nodiscard]] std::size_t predictedTriangleCount(const SubdivisionCage& cage, int level);

/// Builds the tables for a validated cage and a level in [0, kMaxLevel]. Throws
/// SubdivisionError when OpenSubdiv refuses the topology or misses a limit location.
[[nodiscard]] SubdivisionTables buildSubdivisionTables(const SubdivisionCage& cage, SubdivisionSettings settings);

/// The limit stencils (positions, ∂/∂u, ∂/∂v over cage vertices) of `locations`, from a
/// feature-adaptive refinement (kLimitIsolationLevel) of the cage. Fills the three row sets
/// of `tables`.
void buildLimitStencils(const SubdivisionCage& cage, const std::vector<LimitLocation>& locations,
                        SubdivisionTables& tables);

} // namespace trimlab
