#pragma once
/// \file
/// The fixed camera path of `trimlab bench`: cameras evenly spaced on a circle around the
/// scene's vertical (y) axis, looking down at the centre, each framed like the GUI's
/// fitCamera. Deterministic: the same scene, count and aspect give the same cameras.

#include "core/mesh/triangle_mesh.h"
#include "core/view/camera.h"

#include <vector>

namespace trimlab::app {

/// Elevation of the path above the horizontal plane through the centre, in degrees.
inline constexpr double kBenchViewElevationDegrees = 25.0;
/// Azimuth of the first camera, in degrees (off the axes, so no cube face is seen exactly
/// edge-on).
inline constexpr double kBenchViewFirstAzimuthDegrees = 20.0;

/// `count` (>= 1) cameras for width/height `aspect`; camera i sits at azimuth
/// first + 360° · i / count. Empty when `bounds` is not valid or count < 1.
[[nodiscard]] std::vector<Camera> benchViews(const Bounds& bounds, double aspect, int count);

} // namespace trimlab::app
