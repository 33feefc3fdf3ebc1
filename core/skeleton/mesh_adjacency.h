#pragma once
/// \file
/// The vertex graph of a triangle mesh with its edge lengths, for walks over the surface:
/// the rerouting's shortest paths (skeleton_rerouting.h) and the branch recovery's patches
/// and depths (branch_recovery.h).

#include "core/mesh/triangle_mesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace trimlab {

/// Per vertex, its neighbours and the lengths of the edges to them. An edge shared by two
/// triangles is listed twice (harmless for walks; not worth a sort).
using VertexAdjacency = std::vector<std::vector<std::pair<std::uint32_t, double>>>;

[[nodiscard]] VertexAdjacency vertexAdjacency(const TriangleMesh& mesh);

} // namespace trimlab
