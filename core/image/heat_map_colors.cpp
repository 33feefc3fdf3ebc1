#include "core/image/heat_map_colors.h"

#include "core/image/packed_rgba8.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace trimlab {

namespace {

/// The ramp's stops, evenly spaced over [0, 1].
constexpr std::array<glm::vec3, 5> kStops{{
    {0.05f, 0.10f, 0.55f}, // dark blue
    {0.00f, 0.65f, 0.90f}, // cyan
    {0.20f, 0.80f, 0.25f}, // green
    {0.98f, 0.85f, 0.10f}, // yellow
    {0.85f, 0.08f, 0.05f}, // red
}};

} // namespace

glm::vec3 heatMapColor(double t)
{
    if (std::isnan(t))
        t = 1.0;
    const double scaled = std::clamp(t, 0.0, 1.0) * double(kStops.size() - 1);
    const std::size_t low = std::min(std::size_t(scaled), kStops.size() - 2);
    const float within = float(scaled - double(low));
    return glm::mix(kStops[low], kStops[low + 1], within);
}

std::vector<std::uint32_t> heatMapRgba8(std::span<const double> values, double maxValue)
{
    std::vector<std::uint32_t> colors(values.size());
    const double scale = maxValue > 0.0 ? 1.0 / maxValue : 0.0;
    std::transform(values.begin(), values.end(), colors.begin(),
                   [scale](double value) { return packRgba8(heatMapColor(value * scale)); });
    return colors;
}

} // namespace trimlab
