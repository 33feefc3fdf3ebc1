#pragma once
/// \file
/// Loading triangle meshes from files: the one entry point the GUI, the batch verbs and
/// the tests use. Formats: OBJ, OFF, PLY (ASCII and binary), STL (ASCII and binary),
/// glTF 2.0 (.gltf, .glb), each optionally gzip-compressed (.gz).
///
/// Every loader is strict: a returned mesh has at least one triangle, only in-range
/// indices and only finite coordinates. Anything else in the file is reported as a
/// MeshLoadError (mesh_load_error.h) naming the file, the line or element, and the
/// reason; loaders never crash, assert or read out of bounds on bad input, and declared
/// counts never drive allocations beyond what the data could hold.
/// Per-format details: obj_reader.h, off_reader.h, ply_reader.h, stl_reader.h,
/// gltf_reader.h; polygons are triangulated as polygon_triangulation.h describes.

#include "core/mesh/mesh_load_error.h"
#include "core/mesh/triangle_mesh.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

/// The largest mesh input accepted, compressed or not, and the most a .gz file may
/// decompress to: 2 GiB.
inline constexpr std::size_t kMaxMeshInputBytes = std::size_t(2) << 30;

/// Loads the mesh at `path`. The format comes from the extension (case-insensitive)
/// after stripping a trailing ".gz"; the content is gunzipped when the name ends in
/// ".gz" or the data starts with the gzip magic bytes 1f 8b. Errors name the file as
/// `path.string()`. glTF external buffers are read relative to the file's folder.
/// Throws MeshLoadError for an unknown extension, a missing or unreadable file, an empty
/// file, a file larger than kMaxMeshInputBytes, bad gzip data, and every content error.
[[nodiscard]] TriangleMesh loadMesh(const std::filesystem::path& path);

/// The bytes of a mesh-like input file (meshes, cages, animations) as loadMesh reads them:
/// only a regular file (a folder, FIFO, device, socket or symbolic-link loop is refused
/// before anything is opened), at most 2 GiB. Throws MeshLoadError naming `displayName`.
[[nodiscard]] std::string readMeshInputFile(const std::filesystem::path& path, const std::string& displayName);

/// Loads a mesh from `bytes` (possibly gzip-compressed) in the format named by
/// `extension`: "obj", ".obj", "OBJ", "obj.gz", ... . `displayName` names the data in
/// errors. glTF external buffers cannot be resolved (there is no folder) and are
/// reported as errors; embedded (data: URI) buffers and .glb work.
[[nodiscard]] TriangleMesh loadMeshFromMemory(std::string_view bytes, std::string_view extension,
                                              const std::string& displayName);

/// Every extension loadMesh accepts, without dots, lower case: obj, off, ply, stl, gltf,
/// glb, then each with ".gz" appended (for file dialog filters).
[[nodiscard]] std::vector<std::string> supportedMeshExtensions();

} // namespace trimlab
