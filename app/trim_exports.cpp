#include "app/trim_exports.h"

#include "render/image_file.h"

#include <glm/geometric.hpp>

#include <limits>
#include <stdexcept>

namespace trimlab::app {

io::FloatImage rayDistanceImage(const TrimImage& trim, const Camera& camera)
{
    io::FloatImage image{trim.width, trim.height, std::vector<float>(trim.pixels.size())};
    for (int y = 0; y < trim.height; ++y) {
        for (int x = 0; x < trim.width; ++x) {
            const TrimPixel& p = trim.at(x, y);
            float& out = image.values[std::size_t(y) * trim.width + x];
            if (!p.covered()) {
                out = std::numeric_limits<float>::infinity();
                continue;
            }
            // viewDepth is the ray parameter of a direction with view-space z = -1.
            const PixelRay ray = pixelRay(camera, trim.width, trim.height, x, y);
            out = float(double(p.viewDepth) * glm::length(ray.direction));
        }
    }
    return image;
}

QImage idImage(const TrimImage& trim)
{
    QImage image(trim.width, trim.height, QImage::Format_RGBA64);
    for (int y = 0; y < trim.height; ++y) {
        auto* row = reinterpret_cast<QRgba64*>(image.scanLine(y));
        for (int x = 0; x < trim.width; ++x) {
            const TrimPixel& p = trim.at(x, y);
            const auto primitive = static_cast<std::uint32_t>(std::max(p.primitiveId, 0));
            row[x] = p.covered() ? QRgba64::fromRgba64(quint16(p.objectId + 1), quint16(primitive & 0xFFFFu),
                                                       quint16(primitive >> 16), 65535)
                                 : QRgba64::fromRgba64(0, 0, 0, 65535);
        }
    }
    return image;
}

void saveImage(const QImage& image, const QString& path)
{
    render::writeImageFile(image, path);
}

} // namespace trimlab::app
