#pragma once
/// \file
/// A frame of a design for `trimlab render`: a stroke script replayed on a mesh, or a
/// .trimlab project, and which of its frames to show.

#include "app/render_options.h"

#include "core/timeline/timeline.h"

#include <glm/mat4x4.hpp>

#include <string>

namespace trimlab::app {

struct DesignedFrame {
    timeline::Timeline timeline;
    int frame = 0;               ///< the frame to show
    glm::dmat4 model{1.0};       ///< object to world of the designed mesh
    std::string displayName;     ///< "mesh.obj + strokes.json" or the project's file name
};

/// Loads the design `options` name. Throws MeshLoadError, StrokeScriptError,
/// ProjectFileError, or std::invalid_argument (a source with more than one object or not
/// closed, a --frame beyond the last frame) with a message naming the file.
[[nodiscard]] DesignedFrame loadDesignedFrame(const RenderOptions& options);

} // namespace trimlab::app
