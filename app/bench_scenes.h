#pragma once
/// \file
/// The named scenes of `trimlab bench`, from sparse to dense fragment lists:
/// - the built-in demos (no files needed): demo:pushed-sphere (cut open by z <= 0, the
///   GUI's first view), demo:crossing-loop, demo:nested-spheres (cut open, parity);
/// - bunny-cube-25/-50/-75/-100: the Stanford bunny inside a cube (the thesis's S-buffer
///   test, Figure 5.3), parity rule, with a horizontal clipping plane keeping the lower
///   25 %, 50 %, 75 % or all of the cube: from few pixels with deep fragment lists to many;
/// - bunny-hr (60k triangles), elephant-gallop (85k) and dragon (quartet's 100k-triangle
///   dragon), alternating border rule, unclipped: the densest models;
/// - csg3-500k (545k triangles): the dragon once Loop-subdivided, united with the elephant
///   and minus the bunny-hr, cut open by a plane and capped: the GPU goal scene of
///   docs/gpu-results.md (trimming, three-operand CSG and capping at once).
/// The file scenes read third-party meshes from the shared data folder (../shared/data
/// next to the source tree, or --data DIR); the app itself never needs it, so a missing
/// file only skips its scene. Any other demo:NAME or mesh file is accepted too and drawn
/// with the alternating border rule (untrimmed when the mesh is not a closed surface).

#include "app/scene_composition.h"
#include "core/catalog/scene_source.h"
#include "core/trim/trim_settings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace trimlab::app {

/// A scene ready to render: the loaded geometry and the settings it is drawn with.
struct BenchScene {
    std::string name;
    LoadedScene loaded;
    TrimSettings settings;
};

/// The catalog's names in run order.
[[nodiscard]] std::vector<std::string> benchSceneNames();
/// True for a catalog name.
[[nodiscard]] bool isBenchSceneName(const std::string& name);
/// The shared data folder: $TRIMLAB_DATA_DIR when set, else ../shared/data beside the
/// source tree this binary was built from.
[[nodiscard]] std::filesystem::path defaultBenchDataDirectory();

/// Loads `name` (a catalog name, demo:NAME or a mesh file path). Returns nullopt with the
/// reason in `skipReason` when a catalog scene's file is missing from `dataDirectory`.
/// Throws what loadScene throws for unreadable or malformed files and unknown demos.
[[nodiscard]] std::optional<BenchScene>
loadBenchScene(const std::string& name, const std::filesystem::path& dataDirectory, std::string* skipReason);

/// The scene of `trimlab bench A.obj B.obj ...`: the sources as one scene (loadScenes),
/// placed by `transforms` and drawn with `trim` (trimming off when an object is not a
/// closed surface; a scene project's saved CSG and object rules where `trim` has none). Throws what loadScenes throws, and std::invalid_argument naming the
/// option when a transform, --csg or --object-rule names an object the scene lacks.
[[nodiscard]] BenchScene composeBenchScene(const std::vector<std::string>& sources,
                                           const std::vector<ObjectTransformOption>& transforms,
                                           const TrimSettings& trim);

} // namespace trimlab::app
