#pragma once
/// \file
/// The CPU reference's color image (core/image/rgba_image.h) as a QImage, for PNG output
/// and for showing it in the view when no GPU method can render a frame.

#include "core/image/rgba_image.h"

#include <QImage>

namespace trimlab::render {

/// A deep copy in QImage::Format_RGBA8888, row 0 at the top; a null QImage for an empty
/// image.
[[nodiscard]] QImage toQImage(const RgbaImage& image);

} // namespace trimlab::render
