#pragma once
/// \file
/// PLY reader (ASCII, binary little endian, binary big endian).

#include "core/mesh/triangle_mesh.h"

#include <string>
#include <string_view>

namespace trimlab {

/// Reads a PLY file held in `bytes`.
/// - Vertices: element `vertex` with scalar properties x, y, z of any scalar type; other
///   properties (normals, colours, lists) are skipped.
/// - Faces: element `face` with a list property `vertex_indices` or `vertex_index` (any
///   integer count type, any index type); polygons are triangulated
///   (polygon_triangulation.h); other properties are skipped.
/// - Other elements (edge, material, ...) are skipped in all three encodings.
/// Throws MeshLoadError (with the header line, or "vertex N"/"face N" and the ASCII line
/// or binary byte offset) for a bad header, missing x/y/z or face list, truncated data,
/// non-numeric ASCII values, non-finite coordinates, faces with fewer than 3 vertices,
/// negative or out-of-range indices, and files without faces ("contains no faces").
[[nodiscard]] TriangleMesh readPly(std::string_view bytes, const std::string& displayName);

} // namespace trimlab
