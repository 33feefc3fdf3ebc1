#pragma once
/// \file
/// Checking that a loaded pose has the connectivity of the first pose of its sequence.

#include "core/mesh/triangle_mesh.h"

#include <string>
#include <vector>

namespace trimlab {

/// Throws MeshLoadError naming `poseName` unless `pose` has the vertex count
/// `vertexCount` and the triangles `triangles` of the first pose, e.g.
/// "mesh_0007.obj: face 123 is (4, 9, 10) but the first pose has (4, 9, 11)" (face and
/// vertex numbers count from 0, as everywhere in TrimLab).
///
/// One difference is accepted: OBJ, OFF and PLY polygons are triangulated from each
/// pose's own positions (polygon_triangulation.h), so a non-planar quad may be split
/// along its other diagonal in some poses (the walking cat has 8–30 such quads per frame).
/// That is the same surface in the file, so an animator expects the sequence to load.
/// The differing triangles are accepted when, taken together, they cover the same
/// region as the first pose's triangles at those indices — the same vertices and the same
/// directed boundary edges once interior edges (used in both directions) cancel — and
/// the caller then uses the first pose's triangles for every pose.
void requireSameTopology(const std::vector<glm::uvec3>& triangles, std::size_t vertexCount, const TriangleMesh& pose,
                         const std::string& poseName);

} // namespace trimlab
