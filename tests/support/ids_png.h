#pragma once
/// \file
/// Reading the `--ids file.png` that `trimlab render` writes (docs/file-formats.md), with a
/// decoder written from the documentation, independent of the app's encoder, so that the
/// app tests check the file format too.

#include "core/trim/trim_image.h"

#include <QImage>

namespace trimlab::test {

/// The object and primitive ids of an ids PNG (#W×#H, rows from the top): R = object id + 1
/// (0: nothing shown, or a cap), G = primitive id & 0xFFFF, B = primitive id >> 16. Pixels
/// with R = 0 keep TrimPixel's defaults; every other field stays default too. A null image
/// (the file was not written) gives an empty TrimImage.
[[nodiscard]] TrimImage decodeIdsPng(const QImage& png);

/// `full` reduced to what the ids PNG holds (object and primitive ids; the rest default),
/// to compare a reference image with a decoded file.
[[nodiscard]] TrimImage idsOnly(const TrimImage& full);

} // namespace trimlab::test
