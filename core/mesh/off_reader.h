#pragma once
/// \file
/// Object File Format (OFF) reader, as written by CGAL, libigl and Geomview.

#include "core/mesh/triangle_mesh.h"

#include <string>
#include <string_view>

namespace trimlab {

/// Reads the OFF text `text`:
/// ```
/// OFF            (or COFF, NOFF, CNOFF, STOFF, ...; counts may follow on this line)
/// nV nF [nE]
/// x y z [extra values ignored: colours, normals, texture coordinates]   × nV
/// n i0 i1 ... i(n-1) [face colour ignored]                              × nF
/// ```
/// `#` starts a comment; blank lines and a leading UTF-8 byte order mark are skipped. Each
/// vertex and each face is on its own line.
/// Indices count from 0; polygons are triangulated (polygon_triangulation.h).
/// Throws MeshLoadError (line numbers and "vertex N"/"face N") for: a missing or
/// unsupported header (binary OFF, 4D/nD OFF), bad counts, truncation ("the header
/// declares 8 vertices, but the file ends after 5"), non-numeric or non-finite
/// coordinates, faces with fewer than 3 vertices or fewer indices than they declare,
/// negative or out-of-range indices, binary data, and 0 faces ("contains no faces").
/// Declared counts never size an allocation beyond what the remaining bytes could hold.
[[nodiscard]] TriangleMesh readOff(std::string_view text, const std::string& displayName);

} // namespace trimlab
