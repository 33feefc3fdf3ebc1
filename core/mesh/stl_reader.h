#pragma once
/// \file
/// STL reader (ASCII and binary).

#include "core/mesh/triangle_mesh.h"

#include <string>
#include <string_view>

namespace trimlab {

/// Reads an STL file held in `bytes`. The encoding is detected from the content:
/// - binary when the size is exactly 84 + 50·n for the triangle count n at byte 80 (even
///   if the 80-byte header starts with "solid", as many exporters write);
/// - ASCII when the file starts with "solid" and its beginning is text;
/// - otherwise binary (and then usually reported as truncated).
/// Facet normals and attribute bytes are ignored; the vertex order defines orientation.
/// STL has no shared vertices, so bit-identical positions are welded
/// (vertex_welding.h): a closed STL surface comes out closed. Degenerate facets are kept.
/// ASCII facets with more than three vertices are triangulated.
/// Throws MeshLoadError for: files too short to be STL, truncated data (naming the
/// declared triangle count and the bytes present), malformed ASCII (line numbers),
/// non-finite coordinates ("triangle N"), facets with fewer than 3 vertices, and files
/// without facets ("contains no faces").
[[nodiscard]] TriangleMesh readStl(std::string_view bytes, const std::string& displayName);

} // namespace trimlab
