#pragma once
/// \file
/// The segment palette of thesis 3.2.1 (Figure 3.5): an RGB colour wheel with 12
/// divisions — primary, secondary and tertiary hues — visited in an order that puts
/// consecutive colours far apart, larger rings when 12 colours are not enough, and the
/// mixing rules used when a segment inherits from two past segments.

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>

namespace trimlab {

/// A palette colour: `hue` in degrees [0, 360) and `ring` (0 = the 12 fully saturated
/// wheel colours; rings ≥ 1 hold 24 darker hues each, used on overflow).
struct WheelColor {
    double hue = 0.0;
    int ring = 0;

    bool operator==(const WheelColor&) const = default;
    /// RGB in [0, 1]: HSV(hue, s, v) with s = 1, v = 1 on ring 0, darker and paler rings
    /// after it (v = 0.72, 0.5, then 0.35; s alternating 1 and 0.65).
    [[nodiscard]] glm::vec3 rgb() const;
};

/// The `index`-th palette colour. Ring 0 in the order red, green, blue (primary), yellow,
/// cyan, magenta (secondary), orange, spring green, violet, chartreuse, azure, rose
/// (tertiary): each next colour is at least 60° from the one before. Indices 12 … 35
/// form ring 1 (24 hues, 15° apart, in a similar spread order), 36 … 59 ring 2, and so on.
[[nodiscard]] WheelColor paletteColor(std::size_t index);

/// Angular distance of two hues in degrees, in [0, 180].
[[nodiscard]] double hueDistance(double a, double b);

/// Colours a viewer cannot tell apart next to each other: their rgb() lie less than
/// kNearlySameDeltaE apart in CIELAB (ΔE*76). Same-ring hues less than 15° apart always
/// do; hue alone missed the overflow rings' neighbouring hues (15° apart, ΔE 4–13: two
/// dark blues side by side) and ring 0's green beside spring green (ΔE 17.3).
[[nodiscard]] bool nearlySame(const WheelColor& a, const WheelColor& b);
/// The CIELAB distance below which nearlySame() holds.
inline constexpr double kNearlySameDeltaE = 20.0;
/// ΔE*76 between two sRGB colours in [0, 1] (D65).
[[nodiscard]] double deltaE(const glm::vec3& a, const glm::vec3& b);

/// Complementary colours: hues within 15° of opposite (their RGB average is grey).
[[nodiscard]] bool complementary(const WheelColor& a, const WheelColor& b);

/// The mix of two colours for a segment that covers both: the hue halfway along the
/// shorter arc from `a` to `b` (mixing hues, not RGB, so the result is never grey),
/// snapped to the 15° grid, on `a`'s ring. nullopt when the hues are less than 60° apart
/// (the mix would be a near duplicate of both) or complementary (no shorter arc; an RGB
/// mix would be grey): the caller takes a fresh palette colour instead.
[[nodiscard]] std::optional<WheelColor> mixColors(const WheelColor& a, const WheelColor& b);

} // namespace trimlab
