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

} // namespace

double TrimComparison::agreement() const
{
    const int compared = coveredPixels - excluded();
    return compared > 0 ? double(agreeing) / double(compared) : 1.0;
}

double TrimComparison::excludedFraction() const
{
    return coveredPixels > 0 ? double(excluded()) / double(coveredPixels) : 0.0;
}

QString TrimComparison::summary() const
{
    return QStringLiteral("agreement %1 % (%2 of %3 compared pixels; %4 disagree); excluded %5 of %6 covered "
                          "(edge %7, depth order %8, silhouette %9)")
        .arg(100.0 * agreement(), 0, 'f', 3)
        .arg(agreeing)
        .arg(coveredPixels - excluded())
        .arg(disagreeing)
        .arg(excluded())
        .arg(coveredPixels)
        .arg(edgeExcluded)
        .arg(depthExcluded)
        .arg(silhouetteExcluded);
}

TrimComparison compareTrimImages(const TrimImage& actual, const TrimImage& reference,
                                 const ReferenceDiagnostics& diagnostics, const ComparisonTolerance& tolerance)
{
    TrimComparison result;
    result.disagreementMask = QImage(reference.width, reference.height, QImage::Format_Grayscale8);
    result.disagreementMask.fill(0);
    for (int y = 0; y < reference.height; ++y) {
        for (int x = 0; x < reference.width; ++x) {
            const TrimPixel& a = actual.at(x, y);
            const TrimPixel& r = reference.at(x, y);
            if (!a.covered() && !r.covered())
                continue;
            ++result.coveredPixels;
            if (samePixel(a, r)) {
                ++result.agreeing;
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
