#pragma once
/// \file
/// An 8-bit RGBA image in memory, the color output of the CPU reference renderer.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace trimlab {

/// width×height pixels, 4 bytes each (R, G, B, A), row 0 at the top, rows tightly packed
/// (`rgba.size() == 4·width·height`). A default-constructed image is empty (0×0).
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    RgbaImage() = default;
    /// Transparent black. Negative sizes are treated as 0.
    RgbaImage(int w, int h)
        : width(w > 0 ? w : 0), height(h > 0 ? h : 0), rgba(std::size_t(width) * std::size_t(height) * 4, 0)
    {
    }
    /// Pointer to the 4 bytes of pixel (x, y); no bounds check.
    [[nodiscard]] std::uint8_t* at(int x, int y) { return rgba.data() + offset(x, y); }
    [[nodiscard]] const std::uint8_t* at(int x, int y) const { return rgba.data() + offset(x, y); }

private:
    [[nodiscard]] std::size_t offset(int x, int y) const
    {
        return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
    }
};

} // namespace trimlab
