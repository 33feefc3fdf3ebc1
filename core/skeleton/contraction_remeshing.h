#pragma once
/// \file
/// Remeshing while contracting (the connectivity surgery of Au et al. done during
/// contraction, as CGAL's mean-curvature-flow skeleton does): after each solve,
/// edges that became shorter than a length ε collapse to their midpoint, so collapsed
/// cross-sections become single vertices, the triangles that were slivers disappear and
/// the linear system shrinks with every iteration. Without it the contraction keeps every
/// vertex to the end: near-degenerate triangles whose clamped cotangents turn negative
/// then admit solutions far from the surface (webs between limbs), the area rises and the
/// contraction has to stop while wide parts are still sheets.
///
/// A collapse keeps the surface a closed 2-manifold of the same genus: edge (a, b) with
/// opposite vertices c and d collapses only when a and b have no common neighbour but c
/// and d (the link condition), and c and d keep at least three neighbours (a tetrahedron
/// is never flattened into a doubled triangle).

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace trimlab {

struct CollapsedMesh {
    std::vector<glm::dvec3> positions; ///< the surviving vertices
    std::vector<glm::uvec3> triangles; ///< re-indexed to them, orientation kept
    std::vector<int> newIndex;         ///< per input vertex: the surviving vertex that holds it
    std::size_t collapses = 0;
};

/// Collapses edges of `triangles` (a closed manifold over `positions`) shorter than
/// `minLength`, shortest first as measured before any collapse; an edge that grew past
/// minLength through an earlier collapse in the same pass is skipped. Each collapse moves
/// the kept vertex to the edge's midpoint. With no collapse the output equals the input
/// (newIndex the identity). O(E log E).
[[nodiscard]] CollapsedMesh collapseShortEdges(std::span<const glm::dvec3> positions,
                                               std::span<const glm::uvec3> triangles, double minLength);

} // namespace trimlab
