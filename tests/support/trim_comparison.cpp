#include "trim_comparison.h"

#include <algorithm>

namespace trimlab::test {

namespace {

bool samePixel(const TrimPixel& a, const TrimPixel& b)
{
    return a.covered() == b.covered() && a.primitiveId == b.primitiveId && a.objectId == b.objectId &&
           a.facing == b.facing && a.windingAtStart == b.windingAtStart;
}

bool isReferenceSilhouette(const TrimImage& reference, int x, int y)
{
    bool covered = false;
    bool empty = false;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, reference.width - 1);
            const int ny = std::clamp(y + dy, 0, reference.height - 1);
            (reference.at(nx, ny).covered() ? covered : empty) = true;
        }
    }
    return covered && empty;
}

bool tiedWithShown(const PixelTrace& trace, const TrimPixel& actual)
{
    if (trace.walk.shownIndex < 0 || actual.windingAtStart != trace.pixel.windingAtStart)
        return false;
    const RayHit& shown = trace.hits[std::size_t(trace.walk.shownIndex)];
    for (const RayHit& hit : trace.hits) {
        if (hit.t == shown.t && hit.facing == shown.facing && hit.objectId == actual.objectId &&
            hit.primitiveId == actual.primitiveId && hit.facing == actual.facing)
            return true;
    }
    return false;
}

} // namespace

TieCheck referenceTieCheck(const ReferenceRenderer& reference, const Camera& camera, int width, int height,
                           const TrimSettings& settings)
{
    return [&reference, camera, width, height, settings](int x, int y, const TrimPixel& actual) {
        return tiedWithShown(reference.tracePixel(camera, width, height, x, y, settings), actual);
    };
}

double TrimComparison::agreement() const
{
    const int compared = coveredPixels - excluded() - overflowed;
    return compared > 0 ? double(agreeing) / double(compared) : 1.0;
}

double TrimComparison::excludedFraction() const
{
    return coveredPixels > 0 ? double(excluded()) / double(coveredPixels) : 0.0;
}

QString TrimComparison::summary() const
{
    return QStringLiteral("agreement %1 % (%2 of %3 compared pixels, %10 by depth ties; %4 disagree); "
                          "excluded %5 of %6 covered (edge %7, depth order %8, silhouette %9); %11 reported overflowed "
                          "(%12 of them differ)")
        .arg(100.0 * agreement(), 0, 'f', 3)
        .arg(agreeing)
        .arg(coveredPixels - excluded() - overflowed)
        .arg(disagreeing)
        .arg(excluded())
        .arg(coveredPixels)
        .arg(edgeExcluded)
        .arg(depthExcluded)
        .arg(silhouetteExcluded)
        .arg(tieAgreeing)
        .arg(overflowed)
        .arg(overflowedDisagreeing);
}

TrimComparison compareTrimImages(const TrimImage& actual, const TrimImage& reference,
                                 const ReferenceDiagnostics& diagnostics, const ComparisonTolerance& tolerance,
                                 const TieCheck& ties)
{
    TrimComparison result;
    result.disagreementMask = QImage(reference.width, reference.height, QImage::Format_Grayscale8);
    result.disagreementMask.fill(0);
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const TrimPixel& a = actual.at(x, y);
            const TrimPixel& r = reference.at(x, y);
            if (!a.covered() && !r.covered() && !a.unresolved)
                continue;
            ++result.coveredPixels;
            if (a.overflowed || a.unresolved) {
                ++result.overflowed;
                result.overflowedDisagreeing += samePixel(a, r) ? 0 : 1;
                continue;
            }
            if (samePixel(a, r)) {
                ++result.agreeing;
                continue;
            }
            if (ties && a.covered() && r.covered() && ties(x, y, a)) {
                ++result.agreeing;
                ++result.tieAgreeing;
                continue;
            }
            const std::size_t i = diagnostics.index(x, y);
            if (diagnostics.depthMargin[i] < tolerance.relativeDepthTolerance)
                ++result.depthExcluded;
            else if (r.covered() && diagnostics.edgeDistancePx[i] < tolerance.edgeTolerancePx)
                ++result.edgeExcluded;
            else if (a.covered() != r.covered() && isReferenceSilhouette(reference, x, y))
                ++result.silhouetteExcluded;
            else {
                ++result.disagreeing;
                result.disagreementMask.scanLine(y)[x] = 255;
            }
        }
    }
    return result;
}

QImage trimImageToPicture(const TrimImage& image)
{
    QImage picture(image.width, image.height, QImage::Format_RGB32);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const TrimPixel& p = image.at(x, y);
            if (!p.covered()) {
                picture.setPixel(x, y, qRgb(0, 0, 0));
                continue;
            }
            // A cheap integer hash spreads neighbouring primitive ids over the hue circle.
            const unsigned h = unsigned(p.primitiveId) * 2654435761u + unsigned(p.objectId) * 40503u;
            const int scale = p.facing > 0 ? 255 : 150;
            picture.setPixel(x, y, QColor::fromHsv(int(h % 360u), 200, scale).rgb());
        }
    }
    return picture;
}

} // namespace trimlab::test
