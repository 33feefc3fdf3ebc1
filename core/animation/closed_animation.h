#pragma once
/// \file
/// A mesh animation with its holes closed (core/mesh/hole_fans.h): the same fan
/// triangles appended to the shared connectivity, each pose's new vertices at the
/// centroids of its own loop corners. The trim rules, static and dynamic, need a closed
/// surface in every pose; horse-gallop, horse-collapse and walking-cat are open.

#include "core/animation/mesh_animation.h"

namespace trimlab {

/// `animation` closed; unchanged when it has no boundary edges. Throws
/// std::invalid_argument when its boundary edges do not form loops (boundary_loops.h).
[[nodiscard]] MeshAnimation closeAnimationHoles(const MeshAnimation& animation);

} // namespace trimlab
