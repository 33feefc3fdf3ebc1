#pragma once
/// \file
/// A mesh animation with its holes closed (core/mesh/hole_fans.h): the same fan
/// triangles appended to the shared connectivity, each pose's new vertices at the
/// centroids of its own loop corners. The trim rules, static and dynamic, need a closed
/// surface in every pose; horse-gallop, horse-collapse and walking-cat are open. Every
/// pose's fans are checked against that pose's mesh (core/trim/hole_closing.h): a pose
/// that folds the rim so that a fan crosses the surface is reported, naming the pose.

#include "core/animation/mesh_animation.h"
#include "core/trim/hole_closing.h"

namespace trimlab {

/// `animation` closed, and into `closing` (when given) what was closed with the first
/// pose where a fan crosses that pose's mesh ("pose 3: " + fanCrossingMessage) and the
/// number of such poses; unchanged when it has no boundary edges. Throws
/// std::invalid_argument when its boundary edges do not form loops (boundary_loops.h).
/// The closed animation has no skin (AnimationSkin binds the open mesh's vertices only);
/// its poses are kept as they are.
[[nodiscard]] MeshAnimation closeAnimationHoles(const MeshAnimation& animation, HoleClosing* closing = nullptr);

} // namespace trimlab
