#pragma once
/// \file
/// Scene sources for editable surfaces (catalog/scene_source.h delegates here): NURBS JSON
/// files (nurbs_json.h) and built-in surface demos. Each surface becomes one scene object:
/// its tessellation at its own control points (identity model matrix).

#include "core/scene/scene.h"
#include "core/surface/surface_definition.h"
#include "core/timeline/timeline.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

/// True for a path ending in ".nurbs.json" or ".nurbs" (case-insensitive): a NURBS file
/// in the format of nurbs_json.h.
[[nodiscard]] bool isNurbsFileName(std::string_view path);

/// One object per surface of the NURBS file at `path`, named after the surface (or
/// "surface N" when unnamed), tessellated with the default density. Throws
/// NurbsFileError for the file, std::invalid_argument when a surface cannot be
/// tessellated.
[[nodiscard]] Scene nurbsFileScene(const std::string& path);

/// The surface demos, in menu order: "nurbs-sphere", "nurbs-torus", "nurbs-fig8-13"
/// (the last frame of fig8_13NurbsHistory, the static geometry of the figure),
/// "subdivision-cube", "subdivision-torus", "subdivision-push" (the last frame of
/// subdivisionPushHistory).
[[nodiscard]] std::vector<std::string> surfaceDemoNames();
/// A one-line description; empty for an unknown name.
[[nodiscard]] std::string_view surfaceDemoDescription(std::string_view name);
/// The definition behind a surface demo (nullopt for "nurbs-fig8-13", which is a
/// history, and for unknown names): what "Create" in the GUI can start a history from.
[[nodiscard]] std::optional<SurfaceDefinition> surfaceDemoDefinition(std::string_view name);
/// Builds surface demo `name`; nullopt for an unknown name.
[[nodiscard]] std::optional<Scene> makeSurfaceDemoScene(std::string_view name);
/// How the GUI edits an opened surface demo ("demo:nurbs-sphere", …) through its control
/// points: the history of its definition (surfaceDemoDefinition), when that history's
/// base mesh is exactly `shown`, the mesh the loaded scene shows. nullopt for any other
/// source (those start a plain mesh history), for a mesh that differs, and when the
/// surface cannot be built (the demo then shows as a plain mesh).
[[nodiscard]] std::optional<timeline::Timeline> surfaceDemoHistory(std::string_view source, const TriangleMesh& shown);

/// The deformation history behind a surface demo that has one ("nurbs-fig8-13":
/// fig8_13NurbsHistory(), "subdivision-push": subdivisionPushHistory(), both with
/// confluent sets); nullopt for every other name. `trimlab render demo:NAME` renders its
/// frames like a project (--frame, --classification).
[[nodiscard]] std::optional<timeline::Timeline> surfaceDemoHistory(std::string_view name);
/// True when surfaceDemoHistory(name) has a history (cheap: builds nothing).
[[nodiscard]] bool hasSurfaceDemoHistory(std::string_view name);

} // namespace trimlab
