#pragma once
/// \file
/// Loop subdivision of a triangle mesh (C. Loop, 1987) through OpenSubdiv's Far API:
/// uniform refinement of the topology (Far::TopologyRefiner, Sdc::SCHEME_LOOP) and
/// interpolation of the positions level by level (Far::PrimvarRefiner). Each level splits
/// every triangle into four and moves every vertex by Loop's masks, so the limit surface
/// is smooth (C² away from extraordinary vertices); boundaries, where a mesh has them,
/// follow the cubic B-spline boundary rule with their ends kept (edge-only boundary
/// interpolation). The skeleton verb uses it to reach the paper's mesh sizes; surface
/// modelling reuses it.

#include "core/mesh/triangle_mesh.h"

#include <cstddef>

namespace trimlab {

/// The most triangles loopSubdivide produces (4^levels · #F); beyond it the call is
/// refused instead of exhausting memory.
inline constexpr std::size_t kMaxSubdividedTriangles = std::size_t(64) << 20;

/// `mesh` refined `levels` times (0 returns a copy). The result has #F·4^levels
/// triangles, with the original vertices first (moved by the vertex masks), then the
/// vertices of each level's new edges in OpenSubdiv's order; triangles keep the input's
/// orientation. Positions are computed in double precision and rounded to float once.
/// Throws std::invalid_argument for negative levels, a result above
/// kMaxSubdividedTriangles, an index ≥ #V, a triangle with a repeated vertex, or a
/// non-finite position; std::runtime_error when OpenSubdiv refuses the topology.
[[nodiscard]] TriangleMesh loopSubdivide(const TriangleMesh& mesh, int levels);

} // namespace trimlab
