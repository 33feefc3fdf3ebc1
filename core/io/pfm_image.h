#pragma once
/// \file
/// Portable Float Map (PFM) images: the format of `trimlab render --depth`.
/// Grayscale ("Pf"), 32-bit IEEE floats, little endian (scale −1.0), rows stored bottom to
/// top as the format requires. TrimLab writes the distance along each pixel's view ray;
/// pixels that show no surface hold +infinity.

#include <filesystem>
#include <string>
#include <vector>

namespace trimlab::io {

/// width×height floats, row 0 at the top (the in-memory convention everywhere in TrimLab).
struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> values;
};

/// Writes `image` as a grayscale PFM. Throws std::runtime_error naming the file on I/O failure.
void writePfm(const std::filesystem::path& path, const FloatImage& image);

/// Reads a grayscale little- or big-endian PFM. Throws std::runtime_error naming the file
/// and the problem (wrong magic, bad header, truncated data).
[[nodiscard]] FloatImage readPfm(const std::filesystem::path& path);

} // namespace trimlab::io
