#pragma once
/// \file
/// The part of space a clipping set keeps (clip_set.h), within a box, as a closed convex
/// mesh: what the exact export intersects the trimmed solid with to give the solid as the
/// view shows it, cut by the planes and closed by caps on them
/// (core/solid/trimmed_solid.h, cutTrimmedSolid). The box only bounds the infinite
/// half-spaces; it must contain the solid so that its faces bound nothing kept.
///
/// Built from its planes, not by clipping polygons: every vertex is the intersection of
/// three planes, computed once, and every face lists the vertices on its plane in order,
/// so faces share their vertices exactly and the mesh is closed by construction.

#include "core/mesh/triangle_mesh.h"
#include "core/trim/clip_set.h"

namespace trimlab {

/// The convex polytope `box` ∩ {x : every enabled plane of `clips` keeps x}, triangulated,
/// facing outward. Empty (no triangles) when it has no interior (the planes keep nothing
/// of the box) or `box` is not valid.
[[nodiscard]] TriangleMesh clipPolytope(const ClipSet& clips, const Bounds& box);

} // namespace trimlab
