#include "core/deform/brush_settings_check.h"

#include <cmath>
#include <stdexcept>

namespace trimlab::deform {

std::optional<std::string> brushSettingsError(const BrushSettings& settings)
{
    // Negated comparisons so that NaN fails them too.
    if (!(settings.radius > 0.0) || !std::isfinite(settings.radius))
        return "brush radius must be finite and > 0, got " + std::to_string(settings.radius);
    if (!std::isfinite(settings.strength))
        return "brush strength must be finite";
    if (settings.smoothingIterations < 0)
        return "smoothing iterations must be >= 0, got " + std::to_string(settings.smoothingIterations);
    if (!(settings.smoothingStep > 0.0 && settings.smoothingStep <= 1.0))
        return "smoothing step must lie in (0, 1], got " + std::to_string(settings.smoothingStep);
    if (falloffProfileName(settings.profile) == "unknown")
        return "unknown falloff profile " + std::to_string(static_cast<int>(settings.profile));
    if (smoothingWeightsName(settings.smoothingWeights) == "unknown")
        return "unknown smoothing weights " + std::to_string(static_cast<int>(settings.smoothingWeights));
    return std::nullopt;
}

void requireValidBrushSettings(const BrushSettings& settings)
{
    if (const std::optional<std::string> error = brushSettingsError(settings))
        throw std::invalid_argument(*error);
}

} // namespace trimlab::deform
