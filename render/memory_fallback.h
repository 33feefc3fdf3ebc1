#pragma once
/// \file
/// What to render with when the chosen method ran out of GPU memory (GpuMemoryError: the
/// driver's limits, a failed allocation, or the user's memory budget), so the view shows
/// a correct image instead of an error. Each step trades speed for memory:
/// - bounded per-pixel arrays (k⁺-buffer variants, AB_FP: width×height×k slots) → the
///   S-buffer, whose storage is exactly the frame's fragments (exact, unlike a lower k
///   which would leave pixels unresolved);
/// - the S-buffer and the other counted methods (K⁺B-SB, AB_LL), and two-pass → front-to-
///   back peeling: a few per-pixel images, one geometry pass per layer (exact, slower);
/// - peeling → nothing on the GPU: the caller shows the CPU reference for a still image.
/// Under the dynamic rules peeling cannot run (it never holds a pixel's reference and
/// current fragments together), so the S-buffer is the last GPU step there. Likewise when
/// the settings need a method that walks a pixel's whole list in one pass (CSG, the
/// highlights: MethodInfo::inspection): peeling would refuse them, so the CPU still,
/// which does everything, follows the S-buffer.

#include "render/mfr/fragment_method.h"

#include <optional>

namespace trimlab::render {

/// The method to try after `failed` ran out of memory; nullopt: no GPU method is left.
/// `needsInspection`: the frame's settings need a MethodInfo::inspection method
/// (needsInspectionMethod in trim_renderer.h).
[[nodiscard]] std::optional<FragmentMethodKind> memoryFallbackAfter(FragmentMethodKind failed, bool dynamicRules,
                                                                    bool needsInspection = false);

} // namespace trimlab::render
