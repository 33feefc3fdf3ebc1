#include "core/trim/transparency.h"

#include <algorithm>
#include <cmath>

namespace trimlab {

namespace {

double finiteOrZero(double x)
{
    return std::isfinite(x) ? x : 0.0;
}

double clampedAlpha(double alpha)
{
    return std::clamp(finiteOrZero(alpha), 0.0, 1.0);
}

} // namespace

XrayRole xrayRole(const TransparencySettings& settings, bool boundary, bool shownBefore)
{
    if (boundary && settings.display == TrimDisplay::Opaque)
        return shownBefore ? XrayRole::Hidden : XrayRole::Opaque;
    if (boundary)
        return clampedAlpha(settings.layerAlpha) > 0.0 ? XrayRole::Layer : XrayRole::Hidden;
    return clampedAlpha(settings.ghostAlpha) > 0.0 ? XrayRole::Ghost : XrayRole::Hidden;
}

double fresnelAlpha(double alpha, double cosine, double exponent)
{
    alpha = clampedAlpha(alpha);
    exponent = finiteOrZero(exponent);
    if (exponent <= 0.0 || alpha <= 0.0)
        return alpha;
    const double grazing = 1.0 - std::clamp(std::abs(finiteOrZero(cosine)), 0.0, 1.0);
    return alpha + (1.0 - alpha) * std::pow(grazing, exponent);
}

double xrayAlpha(const TransparencySettings& settings, XrayRole role, double cosine)
{
    switch (role) {
    case XrayRole::Hidden:
        return 0.0;
    case XrayRole::Ghost:
        return fresnelAlpha(settings.ghostAlpha, cosine, settings.fresnelExponent);
    case XrayRole::Layer:
        return fresnelAlpha(settings.layerAlpha, cosine, settings.fresnelExponent);
    case XrayRole::Opaque:
        return 1.0;
    }
    return 0.0;
}

void compositeLayer(XrayAccumulator& accumulator, const glm::dvec3& color, double alpha)
{
    accumulator.color += accumulator.transmittance * alpha * color;
    accumulator.transmittance *= 1.0 - alpha;
}

void crossInterval(XrayAccumulator& accumulator, double density, double depth, bool interior)
{
    density = finiteOrZero(density);
    if (interior && density > 0.0 && depth > accumulator.lastDepth)
        accumulator.transmittance *= std::exp(-density * (depth - accumulator.lastDepth));
    accumulator.lastDepth = depth;
}

glm::dvec3 compositeXray(const TransparencySettings& settings, double startDepth, const std::optional<XrayCap>& cap,
                         std::span<const XrayFragment> fragments, const glm::dvec3& background)
{
    XrayAccumulator accumulator;
    accumulator.lastDepth = startDepth;
    bool shown = false;
    if (cap) {
        if (settings.display == TrimDisplay::Opaque)
            return cap->color;
        compositeLayer(accumulator, cap->color, xrayAlpha(settings, XrayRole::Layer, cap->cosine));
        shown = true;
    }
    for (const XrayFragment& fragment : fragments) {
        if (accumulator.done())
            break;
        crossInterval(accumulator, settings.density, fragment.depth, fragment.interiorBefore);
        const XrayRole role = xrayRole(settings, fragment.boundary, shown);
        compositeLayer(accumulator, fragment.color, xrayAlpha(settings, role, fragment.cosine));
        shown = shown || fragment.boundary;
        if (role == XrayRole::Opaque)
            return accumulator.color;
    }
    return accumulator.color + accumulator.transmittance * background;
}

} // namespace trimlab
