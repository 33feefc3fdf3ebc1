#include "render/rgba_qimage.h"

#include <algorithm>

namespace trimlab::render {

QImage toQImage(const RgbaImage& image)
{
    if (image.width <= 0 || image.height <= 0)
        return {};
    QImage result(image.width, image.height, QImage::Format_RGBA8888);
    const std::size_t rowBytes = std::size_t(image.width) * 4;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(&image.rgba[std::size_t(y) * rowBytes], rowBytes, result.scanLine(y));
    return result;
}

} // namespace trimlab::render
