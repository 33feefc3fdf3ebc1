#include "core/image/packed_rgba8.h"

#include <algorithm>
#include <cmath>

namespace trimlab {

std::uint32_t packRgba8(const glm::vec3& rgb)
{
    const auto channel = [](float value) { return std::uint32_t(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); };
    return channel(rgb.r) | channel(rgb.g) << 8 | channel(rgb.b) << 16 | 0xFFu << 24;
}

} // namespace trimlab
