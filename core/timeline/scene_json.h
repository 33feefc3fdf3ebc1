#pragma once
/// \file
/// The "scene" object of a version-3 project file (docs/project-format.md). Internal to
/// core/timeline: project_file.h is the public interface.

#include "core/timeline/project_scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace trimlab::timeline {

/// Throws std::invalid_argument for a scene that cannot be stored: no objects, more than
/// Scene::maxObjects, a non-finite or orientation-reversing model matrix, a triangle
/// index beyond its mesh, or a CSG expression naming a missing object.
[[nodiscard]] nlohmann::json sceneJson(const ProjectScene& scene);

/// Reads and checks the scene at `path`; JsonPathError naming the element otherwise.
[[nodiscard]] ProjectScene readScene(const nlohmann::json& value, const std::string& path);

} // namespace trimlab::timeline
