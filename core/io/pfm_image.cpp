#include "core/io/pfm_image.h"

#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace trimlab::io {

namespace {

std::runtime_error pfmError(const std::filesystem::path& path, const std::string& why)
{
    return std::runtime_error(path.string() + ": " + why);
}

std::uint32_t byteSwap(std::uint32_t v)
{
    return (v >> 24) | ((v >> 8) & 0xFF00u) | ((v << 8) & 0xFF0000u) | (v << 24);
}

float decodeFloat(const char* bytes, bool littleEndian)
{
    std::uint32_t bits = 0;
    std::memcpy(&bits, bytes, 4);
    if (littleEndian != (std::endian::native == std::endian::little))
        bits = byteSwap(bits);
    return std::bit_cast<float>(bits);
}

} // namespace

void writePfm(const std::filesystem::path& path, const FloatImage& image)
{
    std::string bytes = "Pf\n" + std::to_string(image.width) + ' ' + std::to_string(image.height) + "\n-1.0\n";
    bytes.reserve(bytes.size() + 4 * image.values.size());
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x) {
            std::uint32_t bits = std::bit_cast<std::uint32_t>(image.values[std::size_t(y) * image.width + x]);
            if constexpr (std::endian::native != std::endian::little)
                bits = byteSwap(bits);
            bytes.append(reinterpret_cast<const char*>(&bits), 4);
        }
    }
    // A killed run leaves an earlier image whole (core/io/atomic_write.h).
    writeFileAtomically(path, bytes);
}

FloatImage readPfm(const std::filesystem::path& path)
{
    // Only a regular file of at most 1 GiB (core/io/file_bytes.h), parsed from memory.
    std::istringstream in;
    try {
        in.str(readFileBytes(path, std::size_t(1) << 30));
    } catch (const std::runtime_error& e) {
        throw pfmError(path, e.what());
    }
    std::string magic;
    FloatImage image;
    double scale = 0.0;
    in >> magic >> image.width >> image.height >> scale;
    if (magic != "Pf")
        throw pfmError(path, "not a grayscale PFM (magic '" + magic + "', expected 'Pf')");
    if (!in || image.width <= 0 || image.height <= 0 || image.width > 65536 || image.height > 65536 || scale == 0.0)
        throw pfmError(path, "bad PFM header");
    in.get(); // the single whitespace byte before the data
    const std::size_t count = std::size_t(image.width) * std::size_t(image.height);
    // The header's size must not drive the allocation: check what the file holds first.
    const std::streamoff dataStart = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff fileEnd = in.tellg();
    in.seekg(dataStart);
    if (!in || dataStart < 0 || fileEnd - dataStart < std::streamoff(count * 4))
        throw pfmError(path, "truncated: expected " + std::to_string(count) + " floats");
    std::string data(count * 4, '\0');
    if (!in.read(data.data(), std::streamsize(data.size())))
        throw pfmError(path, "truncated: expected " + std::to_string(count) + " floats");
    image.values.resize(count);
    for (int row = 0; row < image.height; ++row)
        for (int x = 0; x < image.width; ++x)
            image.values[std::size_t(image.height - 1 - row) * image.width + x] =
                decodeFloat(&data[(std::size_t(row) * image.width + x) * 4], scale < 0.0);
    return image;
}

} // namespace trimlab::io
