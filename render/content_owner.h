#pragma once
/// \file
/// The layers of what the view shows (shown_content.h) and who publishes into them. Each
/// feature that changes what the view shows is one owner; a layer shows one owner's
/// content at a time, so a reader can always say whose content a frame shows.

#include <string_view>

namespace trimlab::render {

enum class ShownLayer {
    Geometry, ///< the document's scene: objects, meshes, model matrices
    Pose,     ///< object 0's positions
    Colors,   ///< one colour per scene vertex instead of the trim palette
    Chain,    ///< the dynamic rules' chain of reference frames
};

enum class ContentOwner {
    None,              ///< nothing is published
    DesignHistory,     ///< the design session: its shown frame, brush and control-point drags, its chain
    Skeleton,          ///< the Skeleton panel: the posed (or contracted) mesh and the stage colours
    AnimationPlayback, ///< the Timeline: the animation's pose and its chain under a dynamic rule
    Skinning,          ///< the Skinning panel: the approximation's pose and its error heat map
    Segmentation,      ///< the Segmentation panel: the segment colours
    BrushRegion,       ///< the brush's hover: the tinted region it would move
};

/// "design history", "skeleton", … for messages and test output.
[[nodiscard]] std::string_view contentOwnerName(ContentOwner owner);

} // namespace trimlab::render
