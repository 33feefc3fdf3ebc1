#pragma once
/// \file
/// Writing a triangle mesh in the format its file name asks for: Wavefront OBJ (.obj,
/// obj_writer.h), binary little-endian PLY (.ply: float x y z per vertex, a uchar-counted
/// int list per face), binary STL (.stl: a facet normal from each triangle's corners) or
/// glTF 2.0 (.gltf with the buffer embedded, .glb binary: one mesh, one node, one
/// scene). Always through a temporary file and a rename (atomic_write.h).

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace trimlab {

/// True for the extensions above (any case).
[[nodiscard]] bool isMeshExportPath(const std::filesystem::path& path);
/// "obj, ply, stl, gltf or glb", for messages.
[[nodiscard]] std::string meshExportFormatsText();

/// Writes `mesh` to `path`; `comment` names the generator where the format has room.
/// Throws std::invalid_argument for another extension or a triangle index out of range,
/// std::runtime_error naming the file when it cannot be written.
void saveTriangleMesh(const std::filesystem::path& path, const TriangleMesh& mesh, std::string_view comment = {});

} // namespace trimlab
