#include "ids_png.h"

#include <QRgba64>

namespace trimlab::test {

TrimImage decodeIdsPng(const QImage& png)
{
    const QImage image = png.convertToFormat(QImage::Format_RGBA64);
    TrimImage trim(image.width(), image.height());
    for (int y = 0; y < image.height(); ++y) {
        const auto* row = reinterpret_cast<const QRgba64*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            if (row[x].red() == 0)
                continue;
            trim.at(x, y).objectId = row[x].red() - 1;
            trim.at(x, y).primitiveId = row[x].green() + (int(row[x].blue()) << 16);
        }
    }
    return trim;
}

TrimImage idsOnly(const TrimImage& full)
{
    TrimImage reduced(full.width, full.height);
    for (std::size_t i = 0; i < full.pixels.size(); ++i) {
        reduced.pixels[i].primitiveId = full.pixels[i].primitiveId;
        reduced.pixels[i].objectId = full.pixels[i].objectId;
    }
    return reduced;
}

} // namespace trimlab::test
