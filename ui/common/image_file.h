#pragma once
/// \file
/// Writing an image file the way every TrimLab output is written: encoded in memory, then
/// through a temporary file in the same folder and a rename (core/io/atomic_write.h), so
/// that a killed or failed run leaves an earlier file at that path whole.

#include <QImage>
#include <QString>

namespace trimlab::ui {

/// Writes `image` to `path` in `format` ("png"), or when that is empty in the format the
/// path's suffix names (png, jpg, bmp, ...; what QImageWriter supports). Throws
/// std::runtime_error naming the file: an unknown or missing suffix (listing what is
/// supported), an encoder failure, or the write's own errors ("cannot write /a/b.png:
/// rename: Is a directory").
void writeImageFile(const QImage& image, const QString& path, const QByteArray& format = {});

} // namespace trimlab::ui
