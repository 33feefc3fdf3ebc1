#pragma once
/// \file
/// A triangle mesh in a project file: `{"positions": float32 array (x y z per vertex),
/// "triangles": uint32 array (3 indices per triangle)}` (binary_array.h). Shared by the
/// history's base mesh and the objects of a scene project. Internal to core/timeline.

#include "core/mesh/triangle_mesh.h"

#include <nlohmann/json.hpp>

#include <string>

namespace trimlab::timeline {

[[nodiscard]] nlohmann::json meshJson(const TriangleMesh& mesh);

/// The mesh at `path`; JsonPathError for a damaged array or a triangle count that is not
/// a multiple of 3. Indices are not checked against the vertex count here (the history
/// and the scene check them with their own wording).
[[nodiscard]] TriangleMesh readMesh(const nlohmann::json& value, const std::string& path);

} // namespace trimlab::timeline
