#pragma once
/// \file
/// glTF 2.0 reader (.gltf JSON and .glb binary) on top of Debian's tinygltf.

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace trimlab {

/// Reads the glTF asset held in `bytes` (JSON or GLB; detected by the "glTF" magic, so
/// a misnamed file still loads) into one triangle mesh in scene space:
/// - the default scene, else scene 0, else every root node when there are no scenes;
/// - every primitive of mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN, indexed or not
///   (any unsigned index type), transformed by its node's world matrix (node matrix or
///   TRS, composed down the hierarchy); points and lines are skipped;
/// - winding reversed for nodes whose world matrix has a negative determinant (mirrors),
///   so outward-facing triangles stay outward-facing;
/// - bit-identical positions are welded into one vertex (also across primitives), since
///   exporters split vertices at normal/UV seams and trimming needs the shared topology;
/// - normals, UVs, materials, skins, morph targets and animations are ignored; images
///   are never read or decoded.
/// External buffers (`"uri": "mesh.bin"`) are read relative to `baseDir`; when `baseDir`
/// is empty, external files are refused (memory-only input).
/// Throws MeshLoadError for JSON/GLB syntax errors (tinygltf's message), a wrong GLB
/// magic or version, truncated GLB, missing external buffers, invalid node/mesh/accessor
/// references or layouts (naming "mesh M primitive P" and the accessor), out-of-range
/// indices, non-finite positions, node hierarchies that are not trees, required
/// compression extensions (Draco, meshopt), and scenes without triangles ("contains no
/// triangles").
[[nodiscard]] TriangleMesh readGltf(std::string_view bytes, const std::string& displayName,
                                    const std::filesystem::path& baseDir);

} // namespace trimlab
