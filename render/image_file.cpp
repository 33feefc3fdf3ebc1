#include "render/image_file.h"

#include "core/io/atomic_write.h"

#include <QBuffer>
#include <QFileInfo>
#include <QImageWriter>

#include <stdexcept>

namespace trimlab::render {

namespace {

QString supportedSuffixes()
{
    QStringList names;
    for (const QByteArray& format : QImageWriter::supportedImageFormats())
        names << QString::fromLatin1(format);
    return names.join(QStringLiteral(", "));
}

} // namespace

void writeImageFile(const QImage& image, const QString& path, const QByteArray& chosenFormat)
{
    const QByteArray format = chosenFormat.isEmpty() ? QFileInfo(path).suffix().toLower().toLatin1() : chosenFormat;
    if (format.isEmpty() || !QImageWriter::supportedImageFormats().contains(format))
        throw std::runtime_error(path.toStdString() + ": cannot write an image named '." + format.toStdString() +
                                 "'; use one of " + supportedSuffixes().toStdString());
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, format);
    if (!writer.write(image))
        throw std::runtime_error(path.toStdString() + ": cannot encode the image (" +
                                 writer.errorString().toStdString() + ")");
    io::writeFileAtomically(path.toStdString(), std::string_view(bytes.constData(), std::size_t(bytes.size())));
}

} // namespace trimlab::render
