#pragma once
/// \file
/// Conversion between TriangleMesh (flat buffers) and OpenMesh's half-edge triangle mesh,
/// for connectivity work (adjacency walks, smoothing, contraction). Include this header
/// only where OpenMesh is needed; mesh_io.h and triangle_mesh.h stay free of it.
/// trimlab_core links OpenMesh privately, so a target including this header links
/// `OpenMeshCore` itself (as core.openmesh_adapter does in tests/core/CMakeLists.txt).

#include "core/mesh/triangle_mesh.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstddef>
#include <vector>

namespace trimlab {

/// OpenMesh's default traits: float Vec3f points, so positions convert exactly.
using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraits>;

/// The result of toOpenMesh. A half-edge mesh cannot hold every triangle soup: faces that
/// would make an edge or vertex non-manifold, degenerate faces (repeated index) and faces
/// with out-of-range indices are left out and counted here.
struct OpenMeshConversion {
    OpenMeshTriMesh mesh;
    std::size_t rejectedFaces = 0;
    std::vector<std::size_t> rejectedFaceIndices; ///< indices into mesh.triangles, ascending
};

/// Builds an OpenMesh mesh with vertex i = positions[i] (all vertices, referenced or not)
/// and the faces of `mesh` in order, minus the rejected ones. Rejections are counted,
/// never printed: OpenMesh's own error stream is silenced while faces are added.
[[nodiscard]] OpenMeshConversion toOpenMesh(const TriangleMesh& mesh);

/// Flat buffers from an OpenMesh mesh: vertex i = point(VertexHandle(i)) for every vertex
/// slot, faces in handle order with their vertex order (deleted faces skipped; call
/// garbage_collection() first if vertices were deleted).
[[nodiscard]] TriangleMesh fromOpenMesh(const OpenMeshTriMesh& mesh);

} // namespace trimlab
