#pragma once
/// \file
/// The `.trimlab` project file: the base mesh, every frame (stroke or control-point edit,
/// and exact positions), the sets of the deformation history and, for editable surfaces,
/// the surface definition, plus optional view settings. Loading
/// restores the Timeline exactly — bit for bit — and saving replaces the file atomically.
/// The format is documented in docs/project-format.md.

#include "core/timeline/project_file_error.h"
#include "core/timeline/project_scene.h"
#include "core/timeline/timeline.h"
#include "core/timeline/view_settings.h"
#include "core/trim/static_rule.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace trimlab::timeline {

/// The value of the "format" field.
inline constexpr std::string_view kProjectFormatName = "trimlab-project";
/// The newest format version this TrimLab reads. Version 2 adds editable surfaces
/// ("surface", frames with "control_moves"); version 3 adds scenes of several objects
/// ("scene") and the static rules beyond the thesis's three (nonzero, negative, w>=K,
/// |w|>=K). Each file is written with the lowest version that holds it, so older TrimLabs
/// keep opening what they can; every older file reads unchanged.
inline constexpr int kProjectFormatVersion = 3;
/// The largest project file accepted: 4 GiB.
inline constexpr std::size_t kMaxProjectBytes = std::size_t(4) << 30;

/// The camera the GUI showed when the project was saved (object space; as view/camera.h).
struct ProjectView {
    glm::dvec3 eye{0.0, 0.0, 3.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovyDegrees = 45.0; ///< vertical field of view, in (0, 180)

    friend bool operator==(const ProjectView&, const ProjectView&) = default;
};

/// Optional settings stored next to the history; absent ones are simply not written.
struct ProjectExtras {
    std::optional<ProjectView> view;
    std::optional<StaticRule> staticRule;
    /// The rest of the document's view settings (view_settings.h), relative to its bounds.
    std::optional<StoredViewSettings> viewSettings;

    friend bool operator==(const ProjectExtras&, const ProjectExtras&) = default;
};

/// Everything a project file holds: a design history, or (version 3) a scene of objects.
struct Project {
    /// The history; empty (no base mesh) for a scene project.
    Timeline timeline;
    ProjectExtras extras;
    /// Set for a scene project.
    std::optional<ProjectScene> scene;
};

/// The project document as UTF-8 JSON text (what saveProject writes).
/// Throws std::invalid_argument for extras that cannot be stored (a non-finite view).
[[nodiscard]] std::string projectJson(const Timeline& timeline, const ProjectExtras& extras = {});

/// A scene project document (version 3). Throws std::invalid_argument for a scene or
/// extras that cannot be stored (scene_json.h says which).
[[nodiscard]] std::string sceneProjectJson(const ProjectScene& scene, const ProjectExtras& extras = {});

/// Parses a project document. `displayName` names it in errors. Throws ProjectFileError
/// for every problem: not JSON or not a TrimLab project, truncated, a newer version,
/// missing or mistyped fields, damaged binary arrays (bad base64, wrong length, CRC
/// mismatch), unknown rule names, and histories that are inconsistent (sets that do not
/// cover the frames, 'before' positions that disagree with the previous frame, indices
/// out of range, a surface history whose base mesh is not the surface's tessellation —
/// vertex count and triangles, requireSurfaceMatchesTimeline —, which costs one
/// tessellation of the surface). Nothing is returned unless the whole document is valid.
[[nodiscard]] Project parseProject(std::string_view bytes, const std::string& displayName);

/// Writes projectJson(timeline, extras) to `path` atomically (atomic_write.h): on failure
/// an existing file at `path` is untouched. Throws std::runtime_error naming the file.
void saveProject(const Timeline& timeline, const std::filesystem::path& path, const ProjectExtras& extras = {});

/// Writes sceneProjectJson(scene, extras) to `path` atomically, as saveProject.
void saveSceneProject(const ProjectScene& scene, const std::filesystem::path& path, const ProjectExtras& extras = {});

/// Reads and parses the project at `path` (errors name it as `path.string()`); also
/// ProjectFileError when it cannot be read, is not a regular file, is empty or is larger
/// than kMaxProjectBytes.
[[nodiscard]] Project readProject(const std::filesystem::path& path);
/// True when `path` reads as a project document of version 3 or later with a "scene"
/// (a quick look at the JSON, no checks of its contents); false for a history and for
/// anything unreadable, which the full read then reports.
[[nodiscard]] bool isSceneProject(const std::filesystem::path& path);

/// readProject(path) of a design: throws ProjectFileError for a scene project (it has no
/// history), saying so.
[[nodiscard]] Project readHistoryProject(const std::filesystem::path& path);
/// readHistoryProject(path).timeline.
[[nodiscard]] Timeline loadProject(const std::filesystem::path& path);

} // namespace trimlab::timeline
