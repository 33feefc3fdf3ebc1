#include "color_check.h"

#include "image_artifacts.h"

#include <algorithm>
#include <cstdlib>

namespace trimlab::test {

QString ColorComparison::summary() const
{
    return QStringLiteral("colors: %1 of %2 compared pixels within tolerance (%3 %), max difference %4/255, %5 flagged")
        .arg(within)
        .arg(compared)
        .arg(100.0 * agreement(), 0, 'f', 3)
        .arg(maxDifference)
        .arg(flagged);
}

ColorComparison compareColors(const QImage& gpu, const TrimImage& gpuTrim, const RgbaImage& reference,
                              const ReferenceDiagnostics& diagnostics, int tolerance)
{
    ColorComparison result;
    const QImage actual = gpu.convertToFormat(QImage::Format_RGBA8888);
    result.disagreementMask = QImage(reference.width, reference.height, QImage::Format_Grayscale8);
    result.disagreementMask.fill(0);
    for (int y = 0; y < reference.height; ++y) {
        const std::uint8_t* row = actual.constScanLine(y);
        for (int x = 0; x < reference.width; ++x) {
            if (diagnostics.hitCount[diagnostics.index(x, y)] <= 0)
                continue;
            const TrimPixel& flags = gpuTrim.at(x, y);
            if (flags.overflowed || flags.unresolved) {
                ++result.flagged;
                continue;
            }
            const std::uint8_t* expected = reference.at(x, y);
            int difference = 0;
            for (int c = 0; c < 3; ++c)
                difference = std::max(difference, std::abs(int(row[4 * x + c]) - int(expected[c])));
            ++result.compared;
            result.maxDifference = std::max(result.maxDifference, difference);
            if (difference <= tolerance)
                ++result.within;
            else
                result.disagreementMask.scanLine(y)[x] = 255;
        }
    }
    return result;
}

QImage rgbaToImage(const RgbaImage& image)
{
    QImage picture(image.width, image.height, QImage::Format_RGBA8888);
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.at(0, y), 4 * std::size_t(image.width), picture.scanLine(y));
    return picture;
}

std::optional<QString> colorViolation(const ColorComparison& comparison, const QImage& gpu, const RgbaImage& reference,
                                      const QString& name, double minimumAgreement, std::uint64_t minimumCompared)
{
    if (comparison.compared >= minimumCompared && comparison.agreement() >= minimumAgreement)
        return std::nullopt;
    const QString reason = comparison.compared < minimumCompared
                               ? QStringLiteral("only %1 pixels compared: a vacuous case").arg(comparison.compared)
                               : QStringLiteral("too few pixels agree");
    return reason + ": " + comparison.summary() + "; " +
           writeComparisonArtifacts(name, gpu, rgbaToImage(reference), comparison.disagreementMask);
}

} // namespace trimlab::test
