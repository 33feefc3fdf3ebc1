#pragma once
/// \file
/// Which BrushSettings a stroke accepts, as a message (for script and project loaders
/// that report errors) or as an exception (for BrushStroke, applyStroke).

#include "core/deform/stroke.h"

#include <optional>
#include <string>

namespace trimlab::deform {

/// Why `settings` cannot drive a stroke, or nullopt when they can. Valid settings have a
/// finite radius > 0, a finite strength (negative pushes against the drag), an
/// iteration count >= 0, a smoothing step in (0, 1] (λ > 1 overshoots the one-ring
/// average and lets the explicit smoothing oscillate), and enum values that name a
/// profile and a weighting (not integers cast out of range).
[[nodiscard]] std::optional<std::string> brushSettingsError(const BrushSettings& settings);

/// Throws std::invalid_argument with brushSettingsError's message when it has one.
void requireValidBrushSettings(const BrushSettings& settings);

} // namespace trimlab::deform
