#pragma once
/// \file
/// Opening a scene the way every entry point does it (GUI menu, recent files, drag and
/// drop, command line, tests): from a mesh file or a built-in demo ("demo:NAME"), with
/// the validation report that decides whether the trim modes are available.

#include "core/mesh/mesh_validation.h"
#include "core/scene/scene.h"
#include "core/timeline/project_scene.h"
#include "core/trim/inspect_settings.h"
#include "core/trim/static_rule.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

struct LoadedScene {
    Scene scene;
    std::string source;                        ///< as given: a file path or "demo:NAME"
    std::string displayName;                   ///< the file name or the demo name
    std::vector<MeshValidationReport> reports; ///< one per scene object
    /// What a scene project (.trimlab, version 3) saved besides its objects: the CSG
    /// expression with the per-object rules, and the static rule. Empty for other sources.
    CsgSettings savedCsg;
    std::optional<StaticRule> savedRule;

    /// True when every object is a closed, oriented surface (winding numbers defined).
    [[nodiscard]] bool trimmable() const;
    /// Why the trim modes are unavailable ("" when trimmable), naming the object.
    [[nodiscard]] std::string trimUnavailableReason() const;
};

/// The prefix of built-in demo sources.
inline constexpr std::string_view kDemoPrefix = "demo:";

[[nodiscard]] bool isDemoSource(std::string_view source);

/// One built-in demo as the registry lists it: its source ("demo:NAME") and a one-line
/// description.
struct DemoEntry {
    std::string source;
    std::string_view description;
};
/// The registry of built-in demos, in the order help texts and error messages list them:
/// the mesh demos (demo_scenes.h), then the editable-surface demos (surface_scenes.h).
[[nodiscard]] std::vector<DemoEntry> builtInDemos();

/// Loads `source`: a mesh file, a NURBS file (name ending in ".nurbs.json" or ".nurbs",
/// catalog/surface_scenes.h: one tessellated object per surface), a .trimlab project (a
/// scene project's objects with savedCsg and savedRule; a design history's last frame as
/// one object), "demo:NAME" for a demo scene (demo_scenes.h) or a surface demo
/// (surfaceDemoNames(), e.g. "demo:nurbs-sphere"). Throws MeshLoadError for unreadable or
/// malformed files (NURBS and project file errors included, with their JSON path as the
/// element) and std::invalid_argument for an unknown demo name (listing the known ones).
[[nodiscard]] LoadedScene loadScene(const std::string& source);

/// The scene of a scene project: its objects (validated), savedCsg and savedRule.
[[nodiscard]] LoadedScene projectSceneLoaded(const timeline::ProjectScene& scene, const std::optional<StaticRule>& rule,
                                             const std::string& source, const std::string& displayName);

/// The scene project a LoadedScene saves as (objects and CSG; the rule goes into the
/// project's extras).
[[nodiscard]] timeline::ProjectScene projectSceneOf(const LoadedScene& loaded, const CsgSettings& csg);

/// Several sources as one scene (`trimlab render A.obj B.stl --csg "0 - 1"`): the objects
/// of each source in turn, so object ids count across the sources in the order given
/// (a source with two objects takes two ids). The display name joins the sources' names
/// with " + ", `source` is the first source; savedCsg and savedRule are kept only for a
/// single source (the ids of a CSG saved in a later source would be off). Throws what loadScene throws (the error
/// names the file), and std::invalid_argument for no sources or more than
/// Scene::maxObjects objects in all.
[[nodiscard]] LoadedScene loadScenes(const std::vector<std::string>& sources);

} // namespace trimlab
