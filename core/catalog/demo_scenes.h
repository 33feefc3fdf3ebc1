#pragma once
/// \file
/// Built-in demo scenes: deterministic procedural geometry, no files. Names are stable
/// (command line, GUI menu, tests).

#include "core/scene/scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

/// The names of all demo scenes, in menu order: "pushed-sphere", "crossing-loop",
/// "nested-spheres", "sphere", "csg-trio" (three objects for CSG, capping, collisions).
[[nodiscard]] std::vector<std::string> demoSceneNames();

/// A one-line description of demo scene `name`; empty for an unknown name.
[[nodiscard]] std::string_view demoSceneDescription(std::string_view name);

/// Builds demo scene `name`; nullopt for an unknown name. Identity model matrices, every
/// object a closed outward-oriented mesh centred near the origin within radius ~2.
[[nodiscard]] std::optional<Scene> makeDemoScene(std::string_view name);

} // namespace trimlab
