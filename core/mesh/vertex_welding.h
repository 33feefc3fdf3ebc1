#pragma once
/// \file
/// Merging of vertices with bit-identical positions: STL stores every triangle with its
/// own three corners, and glTF splits vertices along UV seams; welding restores the
/// shared vertices so that a closed surface is recognised as closed.

#include "core/mesh/triangle_mesh.h"

namespace trimlab {

/// Returns `mesh` with vertices of identical position merged into the first of them (in
/// vertex order) and triangles renumbered; vertex order is otherwise kept. "Identical"
/// means the same float bit patterns, except that −0 and +0 are treated as equal.
/// Triangles are kept as they are, degenerate ones included. Indices must be in range.
[[nodiscard]] TriangleMesh weldIdenticalVertices(const TriangleMesh& mesh);

} // namespace trimlab
