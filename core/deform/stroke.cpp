#include "core/deform/stroke.h"

namespace trimlab::deform {

std::string_view falloffProfileName(FalloffProfile profile)
{
    switch (profile) {
    case FalloffProfile::Smooth:
        return "smooth";
    case FalloffProfile::Linear:
        return "linear";
    case FalloffProfile::Sharp:
        return "sharp";
    }
    return "unknown"; // only for values cast from out-of-range integers
}

std::optional<FalloffProfile> parseFalloffProfile(std::string_view name)
{
    for (FalloffProfile p : {FalloffProfile::Smooth, FalloffProfile::Linear, FalloffProfile::Sharp}) {
        if (falloffProfileName(p) == name)
            return p;
    }
    return std::nullopt;
}

std::string_view smoothingWeightsName(SmoothingWeights weights)
{
    switch (weights) {
    case SmoothingWeights::Uniform:
        return "uniform";
    case SmoothingWeights::Cotangent:
        return "cotangent";
    }
    return "unknown";
}

std::optional<SmoothingWeights> parseSmoothingWeights(std::string_view name)
{
    for (SmoothingWeights w : {SmoothingWeights::Uniform, SmoothingWeights::Cotangent}) {
        if (smoothingWeightsName(w) == name)
            return w;
    }
    return std::nullopt;
}

} // namespace trimlab::deform
