#pragma once
/// \file
/// Writing a triangle mesh as Wavefront OBJ: a `# TrimLab` header, `v x y z` lines,
/// optionally `vn x y z` lines (one normal per vertex), and 1-based `f a b c` lines
/// (`f a//a b//b c//c` with normals). Floats are printed with "%.9g", enough digits to
/// read back the same float (TrimLab's OBJ reader does).

#include "core/mesh/triangle_mesh.h"

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace trimlab {

/// The OBJ text of `mesh`. `normals` is empty (no `vn` block) or has one entry per vertex.
/// `comment` (may be empty) goes on a second header line `# <comment>`; newlines in it are
/// replaced by spaces. Throws std::invalid_argument when `normals` has another size, or a
/// triangle index is out of range.
[[nodiscard]] std::string meshObjText(const TriangleMesh& mesh, std::span<const glm::vec3> normals = {},
                                      std::string_view comment = {});

/// Throws std::invalid_argument naming `path` and the vertex when a coordinate of `mesh` is
/// not finite ("out.obj: vertex 17 has a non-finite coordinate (inf); nothing was
/// written"). Every mesh writer (this one and mesh_export.h) checks before it writes.
void requireFiniteVertices(const std::filesystem::path& path, const TriangleMesh& mesh);

/// Writes meshObjText to `path` atomically. Throws as meshObjText, and std::runtime_error
/// naming the file when it cannot be written.
void saveMeshObj(const std::filesystem::path& path, const TriangleMesh& mesh, std::span<const glm::vec3> normals = {},
                 std::string_view comment = {});

} // namespace trimlab
