#pragma once
/// \file
/// Joining the vertices that glTF exporters split at normal and UV seams, consistently
/// over all poses of an animation.

#include "core/animation/mesh_animation.h"

namespace trimlab {

/// Merges vertices whose positions are bit-identical (−0 = +0) in every pose into the
/// first of them (in vertex order) and renumbers the triangles; vertex order is otherwise
/// kept. Vertices that coincide in some poses but not in others stay apart, so a seam
/// that opens during the animation is not hidden. Triangles are kept, degenerate ones
/// included. O(#P·#V) expected time.
/// `kept`, when given, receives for each vertex of the result the input vertex it is.
[[nodiscard]] MeshAnimation weldAcrossPoses(const MeshAnimation& animation, std::vector<std::size_t>* kept = nullptr);

} // namespace trimlab
