#include "core/animation/color_wheel.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>

namespace trimlab {

namespace {

// Wheel positions (multiples of 30°) of ring 0 in palette order: primaries, secondaries,
// tertiaries, each next one ≥ 60° from the previous.
constexpr std::array<int, 12> kRingZeroOrder = {0, 4, 8, 2, 6, 10, 1, 5, 9, 3, 7, 11};

// 24 positions (multiples of 15°) visited with a stride of 7 (coprime with 24): 105°
// between consecutive colours of an overflow ring.
int overflowPosition(std::size_t i)
{
    return int((i * 7) % 24);
}

glm::vec3 hsv(double hue, double s, double v)
{
    const double h = std::fmod(hue, 360.0) / 60.0;
    const double c = v * s;
    const double x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
    glm::dvec3 rgb(0.0);
    switch (int(h) % 6) {
    case 0:
        rgb = {c, x, 0};
        break;
    case 1:
        rgb = {x, c, 0};
        break;
    case 2:
        rgb = {0, c, x};
        break;
    case 3:
        rgb = {0, x, c};
        break;
    case 4:
        rgb = {x, 0, c};
        break;
    default:
        rgb = {c, 0, x};
        break;
    }
    return glm::vec3(rgb + glm::dvec3(v - c));
}

// sRGB in [0, 1] to CIELAB (D65 white): linearise, to XYZ, then the CIE L*a*b* curve.
glm::dvec3 cieLab(const glm::vec3& srgb)
{
    const auto linear = [](double u) { return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4); };
    const double r = linear(srgb.r), g = linear(srgb.g), b = linear(srgb.b);
    const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
    const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
    const auto f = [](double t) { return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0; };
    return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

} // namespace

glm::vec3 WheelColor::rgb() const
{
    if (ring == 0)
        return hsv(hue, 1.0, 1.0);
    const double value = ring == 1 ? 0.72 : ring == 2 ? 0.5 : 0.35;
    const double saturation = ring % 2 == 1 ? 1.0 : 0.65;
    return hsv(hue, saturation, value);
}

WheelColor paletteColor(std::size_t index)
{
    if (index < kRingZeroOrder.size())
        return {30.0 * kRingZeroOrder[index], 0};
    const std::size_t overflow = index - kRingZeroOrder.size();
    return {15.0 * overflowPosition(overflow % 24), int(1 + overflow / 24)};
}

double hueDistance(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

bool nearlySame(const WheelColor& a, const WheelColor& b)
{
    return deltaE(a.rgb(), b.rgb()) < kNearlySameDeltaE;
}

double deltaE(const glm::vec3& a, const glm::vec3& b)
{
    return glm::distance(cieLab(a), cieLab(b));
}

bool complementary(const WheelColor& a, const WheelColor& b)
{
    return hueDistance(a.hue, b.hue) > 165.0;
}

std::optional<WheelColor> mixColors(const WheelColor& a, const WheelColor& b)
{
    const double distance = hueDistance(a.hue, b.hue);
    if (distance < 60.0 || complementary(a, b))
        return std::nullopt;
    // Walk from a towards b along the shorter arc.
    const double forward = std::fmod(b.hue - a.hue + 360.0, 360.0);
    const double direction = forward <= 180.0 ? 1.0 : -1.0;
    const double mid = a.hue + direction * distance / 2.0;
    const double snapped = std::fmod(std::round(mid / 15.0) * 15.0 + 360.0, 360.0);
    return WheelColor{snapped, a.ring};
}

} // namespace trimlab
