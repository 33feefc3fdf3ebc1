#include "trim_comparison.h"

#include <algorithm>

namespace trimlab::test {

QString TrimComparison::summary() const
{
    return QString::fromStdString(TrimAgreement::summary());
}

TrimComparison compareTrimImages(const TrimImage& actual, const TrimImage& reference,
                                 const ReferenceDiagnostics& diagnostics, const ComparisonTolerance& tolerance,
                                 const TieCheck& ties)
{
    TrimComparison result;
    static_cast<TrimAgreement&>(result) = measureTrimAgreement(actual, reference, diagnostics, tolerance, ties);
    const std::vector<std::uint8_t>& mask = result.TrimAgreement::disagreementMask;
    result.disagreementMask = QImage(result.width, result.height, QImage::Format_Grayscale8);
    for (int y = 0; y < result.height; ++y)
        std::copy_n(mask.begin() + std::ptrdiff_t(y) * result.width, result.width, result.disagreementMask.scanLine(y));
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
            if (p.isCap()) { // caps: light gray, one shade per plane
                const int shade = 140 + 20 * p.capPlane;
                picture.setPixel(x, y, qRgb(shade, shade, shade));
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
