#pragma once
/// \file
/// The vertex colours of the Skeleton panel's stage views (skeleton_choices.h's
/// SkeletonStageView), RGBA8 as ViewportWidget::setVertexColors takes them (#V each).

#include "core/skeleton/skeleton.h"

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// Fig. 7: ‖L·V′‖ per vertex on the heat map, scaled to the largest finite value (all
/// blue when every value is 0; non-finite values count as 0). `largest` receives the scale.
[[nodiscard]] std::vector<std::uint32_t> laplacianColors(std::span<const double> magnitude, double& largest);

/// Fig. 8: each vertex in the colour of the curve node that absorbed it, the nodes
/// coloured greedily over the curve's edges so that neighbouring nodes always differ
/// (alternating colours along every branch). Vertices mapped to no valid node are grey.
[[nodiscard]] std::vector<std::uint32_t> curveMappingColors(const CurveSkeleton& curve);

/// Fig. 10: each vertex in the palette colour of its rig joint (vertexJoint), grey when invalid.
[[nodiscard]] std::vector<std::uint32_t> jointSegmentColors(const SkeletonRig& rig);

/// Fig. 12: a bone's raw weight column on the heat map over [0, 1] (clamped).
[[nodiscard]] std::vector<std::uint32_t> boneWeightColors(std::span<const double> column);

} // namespace trimlab
