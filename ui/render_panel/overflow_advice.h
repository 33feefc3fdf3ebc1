#pragma once
/// \file
/// What to tell the user when a frame overflowed (a capacity-bounded method lost
/// fragments, so some pixels may be unresolved): which methods would not overflow, and
/// the k that would hold the deepest pixel. A pure function of the frame's statistics, so
/// the panel that shows it stays thin.

#include "render/frame/frame_counters.h"
#include "render/mfr/fragment_method.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace trimlab::ui {

struct OverflowAdvice {
    /// The frame lost fragments (lost > 0) or left pixels unresolved.
    bool overflowing = false;
    /// One or two sentences for the panel ("" when not overflowing).
    QString message;
    /// Methods without a capacity limit, in menu order: switching to one cannot overflow.
    std::vector<render::FragmentMethodKind> unboundedMethods;
    /// The same method with this k (when it uses k and k can still grow).
    std::optional<int> raiseKTo;
    /// raiseKTo is the deepest pixel's fragment count (else a doubling of k).
    bool raiseKHoldsDeepestPixel = false;
};

/// The advice for a frame of `method` with `parameters` whose counters are `counts`.
/// `largestPixelCount`: the largest per-pixel count the method reported (when it keeps
/// counts); taken as the deepest pixel's fragment count only when it exceeds k, since
/// some methods count no more than they hold.
[[nodiscard]] OverflowAdvice adviseOnOverflow(render::FragmentMethodKind method, const render::FrameCounts& counts,
                                              const render::MethodParameters& parameters,
                                              std::optional<std::uint32_t> largestPixelCount);

} // namespace trimlab::ui
