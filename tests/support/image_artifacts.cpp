#include "image_artifacts.h"

#include "test_paths.h"

#include <QColor>

namespace trimlab::test {

QString writeComparisonArtifacts(const QString& name, const QImage& actual, const QImage& expected,
                                 const QImage& disagreementMask)
{
    const QString dir = QString::fromStdString(outputDir().string());
    const QString actualPath = dir + "/" + name + "-actual.png";
    const QString expectedPath = dir + "/" + name + "-expected.png";
    const QString diffPath = dir + "/" + name + "-diff.png";
    actual.save(actualPath);
    expected.save(expectedPath);
    const QImage mask = disagreementMask.convertToFormat(QImage::Format_Grayscale8);
    QImage diff = expected.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < diff.height(); ++y) {
        for (int x = 0; x < diff.width(); ++x) {
            const bool differs = mask.constScanLine(y)[x] != 0;
            const QColor c(diff.pixel(x, y));
            diff.setPixel(x, y, differs ? qRgb(255, 0, 0) : qRgb(c.red() / 3, c.green() / 3, c.blue() / 3));
        }
    }
    diff.save(diffPath);
    return QStringLiteral("artifacts: %1, %2, %3").arg(actualPath, expectedPath, diffPath);
}

} // namespace trimlab::test
