#pragma once
/// \file
/// Writing an image file the way every TrimLab output is written: encoded in memory, then
/// through a temporary file in the same folder and a rename (core/io/atomic_write.h), so
/// that a killed or failed run leaves an earlier file at that path whole. It lives in
/// render, below both the GUI (Save Screenshot) and the batch verbs (`render -o`), because
/// it needs QtGui's image writers (PNG, JPEG, BMP, ... by the file's suffix) and render is
/// the lowest layer that may use QtGui; a PNG-only encoder in core would drop the other
/// formats the verbs accept.

#include <QImage>
#include <QString>

namespace trimlab::render {

/// Writes `image` to `path` in `format` ("png"), or when that is empty in the format the
/// path's suffix names (png, jpg, bmp, ...; what QImageWriter supports). Throws
/// std::runtime_error naming the file: an unknown or missing suffix (listing what is
/// supported), an encoder failure, or the write's own errors ("cannot write /a/b.png:
/// rename: Is a directory").
void writeImageFile(const QImage& image, const QString& path, const QByteArray& format = {});

} // namespace trimlab::render
