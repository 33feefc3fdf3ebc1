#pragma once
/// \file
/// One GPU-vs-reference check of a multi-fragment method, shared by the render tests:
/// render a case with a method, compare with the CPU reference (trim_comparison.h), and
/// say why it fails, if it does (with actual/expected/diff images written).

#include "trim_comparison.h"
#include "render/trim_renderer.h"

#include "core/trim/reference_renderer.h"

#include <QString>

#include <optional>

namespace trimlab::test {

struct MethodCase {
    QString name; ///< used for artifact file names
    Camera camera;
    TrimSettings settings;
    render::MethodParameters parameters;
    int width = 256;
    int height = 192;
};

/// The acceptance criteria of the render tests.
struct MethodCriteria {
    double minimumAgreement = 0.999; ///< on compared pixels
    double maximumExcluded = 0.05;   ///< edge/depth/silhouette exclusions per covered pixel
    double minimumCoverage = 0.05;   ///< covered pixels per image pixel: no vacuous cases
    /// Accept another fragment tied in depth with the reference's shown one (TieCheck).
    /// False: ties must resolve exactly as the reference's walk order (coplanar tests).
    bool allowTies = true;
};

/// Renders `testCase` with `method` on `renderer` (whose scene is already set) and
/// compares with `reference` (computed for the same camera, size and settings by
/// `referenceRenderer`). The settings may hold any inspection settings (clip sets,
/// capping, CSG, highlights): caps, collision flags and coplanar counts are compared
/// pixel by pixel like the shown fragment. Bounded methods may differ only on pixels they flag as
/// overflowed; unbounded ones must flag none and lose no fragment. Returns nullopt on
/// success, else the failure message (artifacts written). `summary` receives the
/// comparison summary either way.
[[nodiscard]] std::optional<QString>
checkMethodAgainstReference(render::TrimRenderer& renderer, render::FragmentMethodKind method,
                            const MethodCase& testCase, const ReferenceRenderer& referenceRenderer,
                            const ReferenceResult& reference, QString* summary = nullptr,
                            const MethodCriteria& criteria = {});

/// The comparison half of checkMethodAgainstReference, for a frame already rendered into
/// `renderer`'s target by other means (e.g. the dynamic rules' renderer).
[[nodiscard]] std::optional<QString>
checkFrameAgainstReference(render::TrimRenderer& renderer, const MethodCase& testCase, const ReferenceResult& reference,
                           const TieCheck& ties, QString* summary = nullptr, const MethodCriteria& criteria = {});

} // namespace trimlab::test
