#pragma once
/// \file
/// The per-pixel partition characterization bit vector of a frame (thesis 8.1.2, PC^r):
/// the interior/exterior class of each interval of the pixel ray between consecutive
/// fragments of that frame. Bit n holds the class of the interval that has n of the
/// frame's fragments behind it (counted from the far side, like the winding index, so
/// the index of a point does not depend on the near or clip plane). The thesis keeps
/// 4×32 bits; we keep 8×32 = 256 layers. A ray with more fragments cannot be
/// characterized: `overflowed` is set and pixels that need it are unresolved.

#include <array>
#include <cstdint>

namespace trimlab {

struct PartitionCharacterization {
    static constexpr int kWords = 8;
    static constexpr int kLayers = 32 * kWords; ///< intervals it can hold (fragments + 1 would need one more)

    std::array<std::uint32_t, kWords> bits{};
    bool overflowed = false;

    [[nodiscard]] bool interior(int interval) const
    {
        return interval >= 0 && interval < kLayers && ((bits[std::size_t(interval) / 32] >> (interval % 32)) & 1u) != 0;
    }
    /// Records the class of `interval`; beyond kLayers it marks the vector overflowed.
    void set(int interval, bool isInterior)
    {
        if (interval < 0 || interval >= kLayers) {
            overflowed = true;
            return;
        }
        const std::uint32_t mask = 1u << (interval % 32);
        std::uint32_t& word = bits[std::size_t(interval) / 32];
        word = isInterior ? (word | mask) : (word & ~mask);
    }
    friend bool operator==(const PartitionCharacterization&, const PartitionCharacterization&) = default;
};

} // namespace trimlab
