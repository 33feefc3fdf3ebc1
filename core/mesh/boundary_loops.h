#pragma once
/// \file
/// The boundary loops of a triangle mesh's connectivity: the cycles formed by the edges
/// that exactly one triangle uses. The winding index every trim needs is defined only for
/// closed surfaces (mesh_validation.h); animations such as horse-gallop and
/// horse-collapse have a hole of a few edges, and closing it (hole_fans.h) starts here.

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// The loops of the edges used by exactly one triangle side, each as its corners in
/// order. A loop runs against the triangles beside it: consecutive corners (l[i],
/// l[i + 1]) and (l.back(), l.front()) are the reverse of a boundary triangle side, so a
/// polygon with these corners closes the hole consistently oriented with the mesh.
/// Loops come in the order of their first boundary edge (by vertex pair); a vertex where
/// two loops touch is left by the loop that reached it through the smaller next vertex.
/// Throws std::invalid_argument when the boundary edges do not form cycles (a vertex
/// with more boundary edges into it than out of it: inconsistent orientation).
[[nodiscard]] std::vector<std::vector<std::uint32_t>> boundaryLoops(std::span<const glm::uvec3> triangles);

} // namespace trimlab
