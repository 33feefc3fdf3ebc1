#pragma once
/// \file
/// The `.trimlab` project file: the base mesh, every frame (stroke or control-point edit,
/// and exact positions), the sets of the deformation history and, for editable surfaces,
/// the surface definition, plus optional view settings. Loading
/// restores the Timeline exactly — bit for bit — and saving replaces the file atomically.
/// The format is documented in docs/project-format.md.

#include "core/timeline/project_file_error.h"
#include "core/timeline/timeline.h"
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
/// The newest format version this TrimLab reads, and the one it writes for histories of
/// editable surfaces (version 2 adds "surface" and frames with "control_moves"). Plain
/// mesh histories are still written as version 1, so older TrimLabs open them; every
/// version-1 file reads unchanged.
inline constexpr int kProjectFormatVersion = 2;
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

    friend bool operator==(const ProjectExtras&, const ProjectExtras&) = default;
};

/// Everything a project file holds.
struct Project {
    Timeline timeline;
    ProjectExtras extras;
};

/// The project document as UTF-8 JSON text (what saveProject writes).
/// Throws std::invalid_argument for extras that cannot be stored (a non-finite view).
[[nodiscard]] std::string projectJson(const Timeline& timeline, const ProjectExtras& extras = {});

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

/// Reads and parses the project at `path` (errors name it as `path.string()`); also
/// ProjectFileError when it cannot be read, is not a regular file, is empty or is larger
/// than kMaxProjectBytes.
[[nodiscard]] Project readProject(const std::filesystem::path& path);
/// readProject(path).timeline.
[[nodiscard]] Timeline loadProject(const std::filesystem::path& path);

} // namespace trimlab::timeline
