#pragma once
/// \file
/// How far a GPU trim image agrees with the exact CPU reference, pixel by pixel: the one
/// definition shared by the render and UI tests (tests/support/trim_comparison.h wraps it)
/// and by `trimlab bench`.
///
/// A pixel counts when either image covers it (or the GPU marks it unresolved). It agrees
/// when both cover it with the same object, primitive and facing (or the same cap plane)
/// and the same winding index at the span start, collision flag and coplanar count. Pixels where a float rasteriser may legitimately decide
/// otherwise are *excluded*, by definitions read from the reference's diagnostics, and
/// counted so that exclusions cannot hide a broken renderer:
/// - depth: the depth order that decided the pixel was within `relativeDepthTolerance` of
///   flipping (ReferenceDiagnostics::depthMargin);
/// - edge: the reference's shown triangle has an edge within `edgeTolerancePx` of the
///   pixel centre (where vertex snapping decides coverage);
/// - silhouette: exactly one image covers the pixel and the reference's 3×3
///   neighbourhood (clamped at the image border) holds both covered and empty pixels.
/// Two more cases are legitimate and counted apart:
/// - tie: coplanar duplicated triangles; the GPU shows another of the fragments at exactly
///   the shown depth, with the same facing and winding (a TieCheck decides);
/// - overflowed: a capacity-bounded method flags the pixel as having lost fragments (or
///   unresolved). It is not compared; a wrong pixel without the flag is disagreeing.

#include "core/trim/reference_diagnostics.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_image.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace trimlab {

/// True when `actual`, shown at pixel (x, y) instead of the reference's answer, is one of
/// the fragments tied exactly in depth with the reference's shown fragment.
using TieCheck = std::function<bool(int x, int y, const TrimPixel& actual)>;

/// True when `actual` has the winding of `trace` and is one of its hits at exactly the
/// depth and facing of the shown hit. False for a pixel the reference leaves empty.
[[nodiscard]] bool tiedWithShown(const PixelTrace& trace, const TrimPixel& actual);

/// A TieCheck that traces the pixel with `reference` (same camera, size and settings as the
/// compared images). `reference` must outlive the returned function.
[[nodiscard]] TieCheck referenceTieCheck(const ReferenceRenderer& reference, const Camera& camera, int width,
                                         int height, const TrimSettings& settings);

struct AgreementTolerance {
    double edgeTolerancePx = 1.0 / 32.0;
    double relativeDepthTolerance = 1e-4;
};

/// The counts of one comparison (or, summed with add(), of several).
struct TrimAgreement {
    int width = 0;
    int height = 0;
    int coveredPixels = 0;         ///< covered in either image, or unresolved
    int agreeing = 0;              ///< including ties
    int tieAgreeing = 0;           ///< of those, agreeing through a depth tie
    int disagreeing = 0;           ///< differ, not excluded, not flagged overflowed
    int overflowed = 0;            ///< flagged overflowed or unresolved by the GPU (not compared)
    int overflowedDisagreeing = 0; ///< of those, the ones that differ
    int edgeExcluded = 0;
    int depthExcluded = 0;
    int silhouetteExcluded = 0;
    /// width×height, row 0 at the top: 255 where disagreeing, else 0.
    std::vector<std::uint8_t> disagreementMask;

    [[nodiscard]] int excluded() const { return edgeExcluded + depthExcluded + silhouetteExcluded; }
    /// covered − excluded − overflowed.
    [[nodiscard]] int compared() const { return coveredPixels - excluded() - overflowed; }
    /// agreeing / compared; 1 when nothing is left to compare.
    [[nodiscard]] double agreement() const;
    /// excluded / covered; 0 when nothing is covered.
    [[nodiscard]] double excludedFraction() const;
    /// Adds the counts of `other` (not its mask): totals over several views.
    void add(const TrimAgreement& other);
    /// One line: agreement, compared, ties, exclusions by kind, overflowed pixels.
    [[nodiscard]] std::string summary() const;
};

/// Compares `actual` with `reference`; both must have the diagnostics' size.
[[nodiscard]] TrimAgreement measureTrimAgreement(const TrimImage& actual, const TrimImage& reference,
                                                 const ReferenceDiagnostics& diagnostics,
                                                 const AgreementTolerance& tolerance = {}, const TieCheck& ties = {});

/// The acceptance criteria of the render tests and the bench.
struct AgreementCriteria {
    double minimumAgreement = 0.999; ///< on compared pixels
    double maximumExcluded = 0.05;   ///< excluded per covered pixel
};

/// Why `agreement` fails `criteria` (nullopt when it passes). A method without a capacity
/// limit (`capacityBounded` false) also fails when it flagged any pixel overflowed or lost
/// any of its `fragmentsLost` fragments.
[[nodiscard]] std::optional<std::string> agreementViolation(const TrimAgreement& agreement,
                                                            const AgreementCriteria& criteria, bool capacityBounded,
                                                            std::uint64_t fragmentsLost);

} // namespace trimlab
