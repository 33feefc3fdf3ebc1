#pragma once
/// \file
/// The checks of a replayed design (a Timeline of stroke sets or control-point edits),
/// shared by the render tests of stroke scripts and of editable surfaces: the GPU's
/// dynamic rules against the exact dynamic reference, and where the last frame differs
/// between the static rule and the dynamic rules.

#include "method_check.h"

#include "core/timeline/timeline.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/trim_image.h"

#include <QString>

#include <optional>

namespace trimlab::test {

/// Renders the last level of `chain` under the dynamic rules with `method` (a method with
/// MethodInfo::dynamicRules) and `testCase`'s parameters, camera, settings and size through
/// a DynamicTrimRenderer on `renderer`, and compares the frame with DynamicReferenceRenderer
/// as checkFrameAgainstReference does (no tie allowance). Returns nullopt on success, else
/// the failure message (artifacts written); `summary` receives the comparison summary.
[[nodiscard]] std::optional<QString>
checkDynamicChainAgainstReference(render::TrimRenderer& renderer, render::FragmentMethodKind method,
                                  const DynamicChain& chain, const MethodCase& testCase, QString* summary = nullptr);

/// The exact references of a design's last frame under both classifications, compared
/// pixel by pixel by shown primitive (triangle index of the designed mesh).
struct StaticDynamicDifference {
    TrimImage dynamic;     ///< DynamicReferenceRenderer of the chain, with mesh triangle ids
    TrimImage staticImage; ///< ReferenceRenderer of the last frame's scene (settings.rule)
    int differing = 0;     ///< pixels whose shown primitive differs
    int elsewhere = 0;     ///< of those: neither image shows a triangle the last set moved
    int deeper = 0;        ///< of those: the static image shows a surface and the dynamic one
                           ///< a farther one or none (a hole where the static rule shows a bump)
};

/// `chain` must be the chain to `design`'s last frame (timeline::frameChain).
[[nodiscard]] StaticDynamicDifference compareStaticAndDynamic(const timeline::Timeline& design,
                                                              const DynamicChain& chain, const Camera& camera,
                                                              int width, int height, const TrimSettings& settings);

} // namespace trimlab::test
