#pragma once
/// \file
/// The arrangement of a scene's triangles: every triangle in world space, refined along
/// its intersections with the others (exactly: triangle_arrangement.h) so that faces meet
/// only at shared edges and vertices; equal points merged; faces over the same three
/// points merged into one face carrying, per object, how much the winding number grows
/// from its front to its back (+1 for an outward face of that object, the sum for a
/// stack of coincident faces, which may cancel). Internal to core/solid.

#include "core/solid/exact_kernel.h"
#include "core/solid/exact_profile.h"
#include "core/util/task_control.h"

#include <array>
#include <cstdint>
#include <vector>

namespace trimlab {
struct Scene;
}

namespace trimlab::solid {

struct RefinedFace {
    std::array<std::uint32_t, 3> vertices{}; ///< counter-clockwise seen from the front
    /// delta[o]: the winding number of object o behind the face minus in front of it.
    std::vector<int> delta;
    /// The input triangle (after stacking) the face's first piece came from: two faces
    /// with one source lie in one plane.
    std::uint32_t source = 0;
};

struct RefinedSoup {
    std::vector<ExactPoint> points;
    std::vector<RefinedFace> faces;
    std::size_t inputTriangles = 0;
    std::size_t degenerateTriangles = 0; ///< zero-area input triangles, dropped (they bound nothing)
    std::size_t cancelledFaces = 0;      ///< stacks of coincident faces whose deltas sum to zero
    ExactProfile profile;                ///< the arrangement's sizes and times
};

/// Refines the scene's triangles (model matrices applied in double precision; those
/// doubles are the exact input). Reports progress through `control` and throws
/// OperationCancelled when cancelled.
[[nodiscard]] RefinedSoup refineScene(const Scene& scene, const TaskControl& control);

} // namespace trimlab::solid
