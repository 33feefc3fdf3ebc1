#pragma once
/// \file
/// Reading a subdivision cage from a Wavefront OBJ file, keeping its polygons (the mesh
/// loaders triangulate; a cage must not be), plus OpenSubdiv's shape-file sharpness tags.

#include "core/surface/subdivision_cage.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace trimlab {

/// Reads the OBJ text `text` as a cage for `scheme`.
/// - `v x y z [w]`: a cage vertex (values after z ignored).
/// - `f a b c ...`: a polygon kept as is; corners `v`, `v/vt`, `v//vn` or `v/vt/vn`
///   (only `v` used), counting from 1, or back from -1 (the latest vertex defined
///   before the face). Faces may name vertices defined later.
/// - `t crease 2k/1/0 a0 b0 ... a(k-1) b(k-1) s`: sharp edges (a_i, b_i), or
///   `t crease 2k/k/0 ... s0 ... s(k-1)` with one sharpness per edge;
///   `t corner n/1/0 v0 ... s` or `t corner n/n/0 ... s0 ...`: sharp vertices.
///   As in OpenSubdiv's shape files, tag vertex indices count from 0. Sharpness ≥ 10
///   is infinitely sharp (kInfiniteSharpness). Other tags are refused.
/// - vt, vn, o, g, s, usemtl, mtllib, l, p, unknown keywords and `#` comments are
///   ignored, as is a UTF-8 byte order mark.
/// Throws MeshLoadError ("FILE:LINE: reason") for: too few or non-numeric coordinates,
/// non-finite coordinates, a face with < 3 corners, index 0, an index out of range, a
/// repeated vertex in a face, a malformed or unknown tag, a non-triangle under Loop,
/// no faces, and every other problem validateCage finds, with the line of the face or tag
/// it belongs to (a non-manifold edge names the third face using it) and validateCage's
/// wording, where cage faces and vertices count from 0.
[[nodiscard]] SubdivisionCage readCageObj(std::string_view text, const std::string& displayName,
                                          SubdivisionScheme scheme = SubdivisionScheme::CatmullClark);

/// Reads the cage at `path` (".obj", or gzip-compressed ".obj.gz" / data starting with
/// the gzip magic). Errors name the file as `path.string()`; a missing, unreadable or
/// empty file is a MeshLoadError too.
[[nodiscard]] SubdivisionCage loadCageObj(const std::filesystem::path& path,
                                          SubdivisionScheme scheme = SubdivisionScheme::CatmullClark);

} // namespace trimlab
