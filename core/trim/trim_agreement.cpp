#include "core/trim/trim_agreement.h"

#include <algorithm>
#include <cstdio>

namespace trimlab {

namespace {

bool samePixel(const TrimPixel& a, const TrimPixel& b)
{
    return a.covered() == b.covered() && a.primitiveId == b.primitiveId && a.objectId == b.objectId &&
           a.facing == b.facing && a.windingAtStart == b.windingAtStart && a.capPlane == b.capPlane &&
           a.collision == b.collision && a.coplanarCount == b.coplanarCount;
}

bool isReferenceSilhouette(const TrimImage& reference, int x, int y)
{
    bool sawCovered = false;
    bool sawEmpty = false;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, reference.width - 1);
            const int ny = std::clamp(y + dy, 0, reference.height - 1);
            if (reference.at(nx, ny).covered())
                sawCovered = true;
            else
                sawEmpty = true;
        }
    }
    return sawCovered && sawEmpty;
}

/// Which kind of exclusion, if any, explains a differing pixel; nullptr when none does.
int* exclusionCounter(TrimAgreement& result, const TrimImage& reference, const ReferenceDiagnostics& diagnostics,
                      const AgreementTolerance& tolerance, int x, int y, bool actualCovered)
{
    const std::size_t i = diagnostics.index(x, y);
    const bool referenceCovered = reference.at(x, y).covered();
    if (diagnostics.depthMargin[i] < tolerance.relativeDepthTolerance)
        return &result.depthExcluded;
    if (referenceCovered && diagnostics.edgeDistancePx[i] < tolerance.edgeTolerancePx)
        return &result.edgeExcluded;
    if (actualCovered != referenceCovered && isReferenceSilhouette(reference, x, y))
        return &result.silhouetteExcluded;
    return nullptr;
}

void classifyPixel(TrimAgreement& result, const TrimImage& actual, const TrimImage& reference,
                   const ReferenceDiagnostics& diagnostics, const AgreementTolerance& tolerance, const TieCheck& ties,
                   int x, int y)
{
    const TrimPixel& a = actual.at(x, y);
    const TrimPixel& r = reference.at(x, y);
    if (!a.covered() && !r.covered() && !a.unresolved)
        return;
    ++result.coveredPixels;
    if (a.overflowed || a.unresolved) {
        ++result.overflowed;
        result.overflowedDisagreeing += samePixel(a, r) ? 0 : 1;
        return;
    }
    if (samePixel(a, r)) {
        ++result.agreeing;
        return;
    }
    if (ties && a.covered() && r.covered() && ties(x, y, a)) {
        ++result.agreeing;
        ++result.tieAgreeing;
        return;
    }
    if (int* counter = exclusionCounter(result, reference, diagnostics, tolerance, x, y, a.covered())) {
        ++*counter;
        return;
    }
    ++result.disagreeing;
    result.disagreementMask[std::size_t(y) * std::size_t(result.width) + std::size_t(x)] = 255;
}

std::string formatText(const char* format, double a, double b = 0.0)
{
    char text[160];
    std::snprintf(text, sizeof text, format, a, b);
    return text;
}

} // namespace

bool tiedWithShown(const PixelTrace& trace, const TrimPixel& actual)
{
    if (trace.walk.shownIndex < 0 || actual.windingAtStart != trace.pixel.windingAtStart)
        return false;
    const RayHit& shown = trace.hits[std::size_t(trace.walk.shownIndex)];
    return std::any_of(trace.hits.begin(), trace.hits.end(), [&](const RayHit& hit) {
        return hit.t == shown.t && hit.facing == shown.facing && hit.facing == actual.facing &&
               hit.objectId == actual.objectId && hit.primitiveId == actual.primitiveId;
    });
}

TieCheck referenceTieCheck(const ReferenceRenderer& reference, const Camera& camera, int width, int height,
                           const TrimSettings& settings)
{
    return [&reference, camera, width, height, settings](int x, int y, const TrimPixel& actual) {
        return tiedWithShown(reference.tracePixel(camera, width, height, x, y, settings), actual);
    };
}

double TrimAgreement::agreement() const
{
    const int n = compared();
    return n > 0 ? double(agreeing) / double(n) : 1.0;
}

double TrimAgreement::excludedFraction() const
{
    return coveredPixels > 0 ? double(excluded()) / double(coveredPixels) : 0.0;
}

void TrimAgreement::add(const TrimAgreement& other)
{
    coveredPixels += other.coveredPixels;
    agreeing += other.agreeing;
    tieAgreeing += other.tieAgreeing;
    disagreeing += other.disagreeing;
    overflowed += other.overflowed;
    overflowedDisagreeing += other.overflowedDisagreeing;
    edgeExcluded += other.edgeExcluded;
    depthExcluded += other.depthExcluded;
    silhouetteExcluded += other.silhouetteExcluded;
}

std::string TrimAgreement::summary() const
{
    return formatText("agreement %.3f %% ", 100.0 * agreement()) + "(" + std::to_string(agreeing) + " of " +
           std::to_string(compared()) + " compared pixels, " + std::to_string(tieAgreeing) + " by depth ties; " +
           std::to_string(disagreeing) + " disagree); excluded " + std::to_string(excluded()) + " of " +
           std::to_string(coveredPixels) + " covered (edge " + std::to_string(edgeExcluded) + ", depth order " +
           std::to_string(depthExcluded) + ", silhouette " + std::to_string(silhouetteExcluded) + "); " +
           std::to_string(overflowed) + " reported overflowed (" + std::to_string(overflowedDisagreeing) +
           " of them differ)";
}

TrimAgreement measureTrimAgreement(const TrimImage& actual, const TrimImage& reference,
                                   const ReferenceDiagnostics& diagnostics, const AgreementTolerance& tolerance,
                                   const TieCheck& ties)
{
    TrimAgreement result;
    result.width = reference.width;
    result.height = reference.height;
    result.disagreementMask.assign(std::size_t(reference.width) * std::size_t(reference.height), 0);
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            classifyPixel(result, actual, reference, diagnostics, tolerance, ties, x, y);
    return result;
}

std::optional<std::string> agreementViolation(const TrimAgreement& agreement, const AgreementCriteria& criteria,
                                              bool capacityBounded, std::uint64_t fragmentsLost)
{
    if (agreement.agreement() < criteria.minimumAgreement)
        return formatText("agreement below %.1f %%", 100.0 * criteria.minimumAgreement);
    if (agreement.excludedFraction() > criteria.maximumExcluded)
        return formatText("more than %.1f %% of the covered pixels excluded", 100.0 * criteria.maximumExcluded);
    if (!capacityBounded && (agreement.overflowed > 0 || fragmentsLost > 0))
        return "an unbounded method reported " + std::to_string(agreement.overflowed) + " overflowed pixels and " +
               std::to_string(fragmentsLost) + " lost fragments";
    return std::nullopt;
}

} // namespace trimlab
