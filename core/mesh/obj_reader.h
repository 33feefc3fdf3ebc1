#pragma once
/// \file
/// Wavefront OBJ reader (geometry only).

#include "core/mesh/triangle_mesh.h"

#include <string>
#include <string_view>

namespace trimlab {

/// Reads the OBJ text `text`.
/// - `v x y z [w | r g b]`: a vertex; values after z are ignored.
/// - `f a b c ...`: a polygon, triangulated (polygon_triangulation.h); each corner is
///   `v`, `v/vt`, `v//vn` or `v/vt/vn`; only `v` is used. Indices count from 1; negative
///   indices count back from the last vertex defined before the face (-1 is the latest).
///   Faces may reference vertices defined later in the file.
/// - Everything else (vt, vn, o, g, s, usemtl, mtllib, l, p, unknown keywords, `#`
///   comments) is ignored, as is a leading UTF-8 byte order mark. Line continuations
///   (`\` at the end of a line) are not supported.
/// Throws MeshLoadError with the line number for: a vertex with fewer than 3 numbers,
/// non-numeric or non-finite coordinates, a face with fewer than 3 corners, index 0,
/// indices out of range (naming the vertex count), binary data, and a file without
/// faces ("contains no faces").
[[nodiscard]] TriangleMesh readObj(std::string_view text, const std::string& displayName);

} // namespace trimlab
