#pragma once
/// \file
/// Opening a scene the way every entry point does it (GUI menu, recent files, drag and
/// drop, command line, tests): from a mesh file or a built-in demo ("demo:NAME"), with
/// the validation report that decides whether the trim modes are available.

#include "core/mesh/mesh_validation.h"
#include "core/scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace trimlab {

struct LoadedScene {
    Scene scene;
    std::string source;      ///< as given: a file path or "demo:NAME"
    std::string displayName; ///< the file name or the demo name
    std::vector<MeshValidationReport> reports; ///< one per scene object

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
/// catalog/surface_scenes.h: one tessellated object per surface), "demo:NAME" for a demo
/// scene (demo_scenes.h) or a surface demo (surfaceDemoNames(), e.g.
/// "demo:nurbs-sphere"). Throws MeshLoadError for unreadable or malformed files (NURBS
/// file errors included, with their JSON path as the element) and
/// std::invalid_argument for an unknown demo name (listing the known ones).
[[nodiscard]] LoadedScene loadScene(const std::string& source);

} // namespace trimlab
