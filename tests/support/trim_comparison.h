#pragma once
/// \file
/// Pixel-by-pixel comparison of a GPU trim image with the exact CPU reference.
///
/// A pixel counts when either image covers it. It agrees when both cover it with the same
/// object, primitive and facing and the same winding index at the span start. Pixels
/// where a float rasteriser may legitimately decide differently are *excluded*, by
/// definitions taken from the reference, and counted so they cannot hide a broken renderer:
/// - edge: the reference's shown triangle has an edge within `edgeTolerancePx` of the
///   pixel centre (vertex snapping to 1/256 px decides coverage there);
/// - depth: the depth order that decided the pixel was within `relativeDepthTolerance`
///   of flipping (ReferenceDiagnostics::depthMargin);
/// - silhouette: exactly one image covers the pixel and the reference's 3×3 neighbourhood
///   has both covered and empty pixels.
/// Two more cases are legitimate and counted apart:
/// - tie: coplanar duplicated triangles; the GPU shows another of the fragments that lie
///   at exactly the shown depth, with the same facing and winding (a `TieCheck` decides);
/// - overflowed: a capacity-bounded method reports that the pixel lost fragments. Such a
///   pixel may differ; a method must report overflow wherever it is wrong, so a wrong pixel
///   without the flag counts as disagreeing.

#include "trim/reference_diagnostics.h"
#include "trim/reference_renderer.h"
#include "trim/trim_image.h"

#include <QImage>
#include <QString>

#include <functional>

namespace trimlab::test {

/// True when `actual`, shown at pixel (x, y) instead of the reference's answer, is one of
/// the fragments tied exactly in depth with the reference's shown fragment.
using TieCheck = std::function<bool(int x, int y, const TrimPixel& actual)>;

/// A TieCheck from the reference's full hit list of the pixel.
[[nodiscard]] TieCheck referenceTieCheck(const ReferenceRenderer& reference, const Camera& camera, int width,
                                         int height, const TrimSettings& settings);

struct ComparisonTolerance {
    double edgeTolerancePx = 1.0 / 32.0;
    double relativeDepthTolerance = 1e-4;
};

struct TrimComparison {
    int coveredPixels = 0;   ///< covered in either image
    int agreeing = 0;        ///< including ties
    int tieAgreeing = 0;     ///< of those, agreeing through a depth tie
    int disagreeing = 0;     ///< differ, not excluded, not reported as overflowed
    int overflowed = 0;      ///< reported as overflowed by the GPU method (not compared)
    int overflowedDisagreeing = 0;
    int edgeExcluded = 0;
    int depthExcluded = 0;
    int silhouetteExcluded = 0;
    QImage disagreementMask; ///< Grayscale8, 255 where disagreeing, row 0 at the top

    [[nodiscard]] int excluded() const { return edgeExcluded + depthExcluded + silhouetteExcluded; }
    /// agreeing / (covered − excluded − overflowed); 1 when nothing is left to compare.
    [[nodiscard]] double agreement() const;
    /// excluded / covered.
    [[nodiscard]] double excludedFraction() const;
    [[nodiscard]] QString summary() const;
};

/// Both images must have the diagnostics' size.
[[nodiscard]] TrimComparison compareTrimImages(const TrimImage& actual, const TrimImage& reference,
                                               const ReferenceDiagnostics& diagnostics,
                                               const ComparisonTolerance& tolerance = {},
                                               const TieCheck& ties = {});

/// A false-color picture of a trim image for failure artifacts: empty pixels black,
/// covered ones colored by primitive id, front-facing brighter than back-facing.
[[nodiscard]] QImage trimImageToPicture(const TrimImage& image);

} // namespace trimlab::test
