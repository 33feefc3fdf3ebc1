#include "core/trim/trim_shading.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

glm::vec3 shadeTrimPoint(int facing, const glm::dvec3& normal, const glm::dvec3& toViewer)
{
    return shadeTrimPoint(facing, normal, toViewer, false);
}

glm::vec3 shadeTrimPoint(int facing, const glm::dvec3& normal, const glm::dvec3& toViewer, bool carved)
{
    const glm::vec3 base = facing > 0 ? kFrontFacingColor : carved ? kCarvedWallColor : kBackFacingColor;
    // Two-sided: the viewer sees whichever side faces it.
    const float diffuse = static_cast<float>(std::abs(glm::dot(normal, toViewer)));
    return base * (kAmbient + (1.0f - kAmbient) * diffuse);
}

} // namespace trimlab

namespace trimlab {

namespace {

float fraction(double x)
{
    return static_cast<float>(x - std::floor(x));
}

} // namespace

void capPatternBasis(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v)
{
    const glm::dvec3 a = glm::abs(n);
    const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1.0, 0.0, 0.0)
                            : a.y <= a.z             ? glm::dvec3(0.0, 1.0, 0.0)
                                                     : glm::dvec3(0.0, 0.0, 1.0);
    u = glm::normalize(glm::cross(n, axis));
    v = glm::cross(n, u);
}

bool onCapLine(const CapSettings& cap, const glm::dvec3& p, const glm::dvec3& n)
{
    if (cap.pattern == CapPattern::Solid || !(cap.spacing > 0.0) || !std::isfinite(cap.spacing))
        return false;
    const float width = std::clamp(static_cast<float>(cap.lineWidth), 0.0f, 1.0f);
    glm::dvec3 u;
    glm::dvec3 v;
    capPatternBasis(n, u, v);
    if (cap.pattern == CapPattern::Striped)
        return fraction(glm::dot(p, u) / cap.spacing) < width;
    const double diagonal = cap.spacing * std::sqrt(2.0);
    return fraction(glm::dot(p, u + v) / diagonal) < width || fraction(glm::dot(p, u - v) / diagonal) < width;
}

glm::vec3 shadeCap(const CapSettings& cap, const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& toViewer)
{
    const float diffuse = static_cast<float>(std::abs(glm::dot(n, toViewer)));
    const glm::vec3 base = onCapLine(cap, p, n) ? kCapLineShade * kFrontFacingColor : kFrontFacingColor;
    return base * (kAmbient + (1.0f - kAmbient) * diffuse);
}

glm::vec3 coplanarColor(int count, const glm::vec3& shaded)
{
    static constexpr glm::vec3 kPalette[] = {
        {0.90f, 0.10f, 0.10f}, // 2 red
        {0.15f, 0.30f, 0.95f}, // 3 blue
        {0.10f, 0.80f, 0.20f}, // 4 green
        {0.10f, 0.90f, 0.90f}, // 5 cyan
        {0.50f, 1.00f, 0.83f}, // 6 aquamarine
        {1.00f, 0.00f, 1.00f}, // 7 fuchsia
        {1.00f, 0.95f, 0.10f}, // 8 yellow
        {0.60f, 0.35f, 0.15f}, // 9+ brown
    };
    if (count < 2)
        return shaded;
    return kPalette[std::min(count, 9) - 2];
}

glm::vec3 applyHighlights(const glm::vec3& shaded, float lighting, bool collision, int coplanarCount)
{
    glm::vec3 color = coplanarCount >= 2 ? coplanarColor(coplanarCount, shaded) * lighting : shaded;
    if (collision)
        color = color + (kCollisionColor * lighting - color) * kCollisionTint;
    return color;
}

} // namespace trimlab
