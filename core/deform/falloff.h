#pragma once
/// \file
/// The falloff profiles f(t), t = d/r: how the warp fades with geodesic distance d from
/// the anchor within the brush radius r.

#include "core/deform/stroke.h"

namespace trimlab::deform {

/// f(t) for t = d/r (t < 0 reads as 0, t >= 1 gives 0; NaN gives 0). Every profile has
/// f(0) = 1, f(1) = 0, and is monotone non-increasing on [0, 1]:
/// - Smooth: (1 − t²)², a C¹ bell: slope 0 at the anchor (no cone tip under the cursor)
///   and at the radius (no crease where the region meets the untouched surface).
/// - Linear: 1 − t (a cone).
/// - Sharp: (1 − t)³, which keeps most of the pull near the anchor (f(0.5) = 1/8).
///   C² at the radius, but with a tip at the anchor.
[[nodiscard]] double falloff(FalloffProfile profile, double t);

} // namespace trimlab::deform
