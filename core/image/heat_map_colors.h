#pragma once
/// \file
/// The error heat map's color scale: a value in [0, max] becomes a color on a ramp from
/// dark blue (0: no error) through cyan, green and yellow to red (max). Used for the
/// per-vertex skinning error on the mesh and for its legend, so both read alike.

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

/// RGB in [0, 1] at `t` ∈ [0, 1] of the ramp (clamped; NaN counts as 1, the alarm end).
[[nodiscard]] glm::vec3 heatMapColor(double t);

/// #values packed RGBA8 colors (packed_rgba8.h) of values[j] / `maxValue`;
/// a `maxValue` ≤ 0 (no error anywhere) maps every value to the cold end.
[[nodiscard]] std::vector<std::uint32_t> heatMapRgba8(std::span<const double> values, double maxValue);

} // namespace trimlab
