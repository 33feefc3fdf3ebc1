#pragma once
/// \file
/// What makes a stroke storable and replayable, checked where strokes enter the
/// timeline so that every saved project loads again.

#include "core/deform/stroke.h"

#include <cstdint>
#include <string>

namespace trimlab::timeline {

/// Upper bound on smoothing iterations: far above any useful value, low enough that a
/// typo in a hand-written script cannot stall a replay for hours.
inline constexpr std::int64_t kMaxSmoothingIterations = 10000;

/// "" when `stroke` is valid, otherwise the first problem, checked in this order: "the
/// anchor is not finite", "the drag is not finite", "the radius must be finite and > 0",
/// "the strength is not finite", "the smoothing step must be in (0, 1]", "the smoothing
/// iterations must be in [0, 10000]".
[[nodiscard]] std::string strokeProblem(const deform::Stroke& stroke);

} // namespace trimlab::timeline
