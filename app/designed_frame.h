#pragma once
/// \file
/// A frame of a design for `trimlab render`: a stroke script replayed on a mesh, or a
/// .trimlab project, and which of its frames to show.

#include "app/render_options.h"

#include "core/timeline/timeline.h"
#include "core/timeline/view_settings.h"

#include <glm/mat4x4.hpp>

#include <optional>
#include <string>

namespace trimlab::app {

struct DesignedFrame {
    timeline::Timeline timeline;
    int frame = 0;           ///< the frame to show
    glm::dmat4 model{1.0};   ///< object to world of the designed mesh
    std::string displayName; ///< "mesh.obj + strokes.json" or the project's file name
    /// What a project was saved with (core/timeline/view_settings.h): its static rule and
    /// classification, which apply where the command line does not choose them.
    std::optional<StaticRule> savedRule;
    std::optional<timeline::Classification> savedClassification;
};

/// The classification and the static rule `design` is rendered with: the command line's
/// where given, else what the project was saved with, else the dynamic rules and --rule's
/// default.
struct DesignedClassification {
    timeline::Classification classification = timeline::Classification::Dynamic;
    StaticRule rule;
};
[[nodiscard]] DesignedClassification designedClassification(const RenderOptions& options, const DesignedFrame& design);

/// Loads the design `options` name. Throws MeshLoadError, StrokeScriptError,
/// ProjectFileError, or std::invalid_argument (a source with more than one object or not
/// closed, a --frame beyond the last frame) with a message naming the file.
[[nodiscard]] DesignedFrame loadDesignedFrame(const RenderOptions& options);

} // namespace trimlab::app
