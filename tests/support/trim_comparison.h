#pragma once
/// \file
/// Pixel-by-pixel comparison of a GPU trim image with the exact CPU reference, for tests:
/// a thin Qt-typed wrapper around core's trim/trim_agreement.h, which defines what agrees,
/// what is excluded (edge, depth order, silhouette), what counts as a depth tie and how
/// overflowed pixels are handled. The counts are TrimAgreement's; the disagreement mask
/// is a QImage and the summary a QString, for failure artifacts and messages.

#include "core/trim/reference_diagnostics.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_agreement.h"
#include "core/trim/trim_image.h"

#include <QImage>
#include <QString>

namespace trimlab::test {

using trimlab::referenceTieCheck;
using trimlab::TieCheck;
using ComparisonTolerance = trimlab::AgreementTolerance;

/// TrimAgreement's counts, with its mask as a Grayscale8 image (255 where disagreeing,
/// row 0 at the top) and its summary as a QString.
struct TrimComparison : TrimAgreement {
    QImage disagreementMask;

    [[nodiscard]] QString summary() const;
};

/// Both images must have the diagnostics' size (see measureTrimAgreement).
[[nodiscard]] TrimComparison compareTrimImages(const TrimImage& actual, const TrimImage& reference,
                                               const ReferenceDiagnostics& diagnostics,
                                               const ComparisonTolerance& tolerance = {}, const TieCheck& ties = {});

/// A false-color picture of a trim image for failure artifacts: empty pixels black,
/// caps gray (lighter for higher plane indices), covered ones colored by primitive id,
/// front-facing brighter than back-facing.
[[nodiscard]] QImage trimImageToPicture(const TrimImage& image);

} // namespace trimlab::test
