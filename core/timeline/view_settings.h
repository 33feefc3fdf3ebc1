#pragma once
/// \file
/// The view settings that belong to a document rather than to the user: how its solid is
/// classified (trim on or off, the static rule, the static or dynamic classification of a
/// design's frames), its clipping planes, caps, highlights and X-ray. A project file
/// stores them next to its history or scene (project_file.h), the GUI restores them when
/// the project opens and `trimlab render` renders the project with them; a document opened
/// without them gets documentDefaults(), never the settings of the document shown before.
///
/// Clipping planes are kept in world space while a document is open (the renderers' form,
/// TrimSettings) and stored relative to the document's bounds (RelativeClipPlane), so a
/// saved cut still cuts the same part of the solid when the file is opened with other
/// object placements, and a box of planes around a scene grows with it when objects are
/// added (refitClipPlanes). The cap pattern's line spacing is a fraction of the bounding
/// radius for the same reason: it follows the scene when an object is scaled.

#include "core/mesh/triangle_mesh.h"
#include "core/trim/clip_set.h"
#include "core/trim/inspect_parameters.h"
#include "core/trim/trim_settings.h"

#include <array>
#include <optional>
#include <string_view>

namespace trimlab::timeline {

/// How the frames of a design are classified: by the static rule alone, or by the dynamic
/// rules of the history's sets (thesis 8.1.1) with the static rule classifying the base
/// mesh.
enum class Classification { Static, Dynamic };

[[nodiscard]] std::string_view classificationName(Classification classification);
/// "static" or "dynamic"; nullopt otherwise.
[[nodiscard]] std::optional<Classification> parseClassification(std::string_view name);

/// A clipping plane relative to a box: the unit `normal` and the signed distance of the
/// box's centre from the plane in units of the box's extent along the normal (its support,
/// the half extents weighted by |normal|). 0: through the centre; 1: touching the box on
/// the side the normal points away from, so the whole box is kept; −1: nothing is kept.
/// A plane on a face of the box stays on that face of any other box.
struct RelativeClipPlane {
    bool enabled = false;
    glm::dvec3 normal{0.0, 0.0, -1.0};
    double centreDistance = 0.0;

    friend bool operator==(const RelativeClipPlane&, const RelativeClipPlane&) = default;
};

/// `plane` (world space) relative to `bounds`; an empty box counts as the unit cube around
/// the origin, and a box flat along the normal measures with its bounding radius. Throws
/// std::invalid_argument for a zero normal.
[[nodiscard]] RelativeClipPlane relativeClipPlane(const ClipPlane& plane, const Bounds& bounds);
/// The world-space plane of `plane` for `bounds` (the inverse of relativeClipPlane).
[[nodiscard]] ClipPlane absoluteClipPlane(const RelativeClipPlane& plane, const Bounds& bounds);

/// A document's view settings in world space, as the renderers take them.
struct DocumentSettings {
    /// Trim on/off, the rule, the clipping planes (world space), caps, highlights and
    /// X-ray. `trim.csg` is not part of it: the CSG expression belongs to the scene
    /// (project_scene.h), and `trim.cap.spacing` is derived (capSpacingFraction).
    TrimSettings trim;
    Classification classification = Classification::Static;
    /// The cap pattern's line spacing as a fraction of the scene's bounding radius.
    /// (range and default: inspect_parameters::kCapSpacing).
    double capSpacingFraction = inspect_parameters::kCapSpacing.defaultValue;

    friend bool operator==(const DocumentSettings&, const DocumentSettings&) = default;
};

/// What a document without saved settings shows: the alternating border rule on the
/// whole solid, plane 0 prepared (normal (0, 0, −1) through the centre of `bounds`) but
/// off, no caps, highlights or X-ray; the dynamic classification when the document
/// arrives with a deformation history that has frames (a project, a replayed script, a
/// demo with edits), since that is what its sets were made for, the static one otherwise.
[[nodiscard]] DocumentSettings documentDefaults(const Bounds& bounds, bool hasHistory);

/// The cap spacing of `settings` for a scene of `bounds`: capSpacingFraction times its
/// bounding radius (1 for an empty box).
[[nodiscard]] double capSpacing(const DocumentSettings& settings, const Bounds& bounds);

/// The clipping planes of `settings` moved from `from` to `to` keeping their place
/// relative to the bounds (a scene grown by added objects keeps its box around it).
[[nodiscard]] DocumentSettings refitClipPlanes(DocumentSettings settings, const Bounds& from, const Bounds& to);

/// The view settings as a project stores them: everything of DocumentSettings but the
/// rule (ProjectExtras::staticRule keeps it) with the planes relative to the bounds.
struct StoredViewSettings {
    bool trimEnabled = true;
    Classification classification = Classification::Static;
    std::array<RelativeClipPlane, kMaxClipPlanes> clips{};
    bool capEnabled = false;
    CapPattern capPattern = CapPattern::Hatched;
    double capSpacingFraction = inspect_parameters::kCapSpacing.defaultValue;
    HighlightSettings highlight;
    TransparencySettings transparency;

    friend bool operator==(const StoredViewSettings&, const StoredViewSettings&) = default;
};

/// `settings` for a project, relative to `bounds`.
[[nodiscard]] StoredViewSettings storedViewSettings(const DocumentSettings& settings, const Bounds& bounds);
/// The document settings `stored` and `rule` describe for a document of `bounds`.
[[nodiscard]] DocumentSettings documentSettings(const StoredViewSettings& stored, StaticRule rule,
                                                const Bounds& bounds);

} // namespace trimlab::timeline
