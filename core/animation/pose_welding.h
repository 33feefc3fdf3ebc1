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
[[nodiscard]] MeshAnimation weldAcrossPoses(const MeshAnimation& animation);

} // namespace trimlab
