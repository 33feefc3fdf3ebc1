#pragma once
/// \file
/// Files `trimlab render` writes besides the color image, documented in
/// docs/file-formats.md so other tools can read them:
/// - depth: a PFM of the distance from the eye along each pixel's view ray to the shown
///   surface point, in scene units; +inf where the pixel shows no surface;
/// - ids: a 16-bit RGBA PNG, R = object id + 1 (0: no surface), G = primitive id & 0xFFFF,
///   B = primitive id >> 16, A = 65535.

#include "core/io/pfm_image.h"
#include "core/trim/trim_image.h"
#include "core/view/camera.h"

#include <QImage>
#include <QString>

namespace trimlab::app {

/// Distances along the view rays (row 0 at the top).
[[nodiscard]] io::FloatImage rayDistanceImage(const TrimImage& trim, const Camera& camera);

/// The id image described above.
[[nodiscard]] QImage idImage(const TrimImage& trim);

/// Saves `image` to `path` (format from the extension); throws std::runtime_error naming
/// the file when Qt cannot write it.
void saveImage(const QImage& image, const QString& path);

} // namespace trimlab::app
