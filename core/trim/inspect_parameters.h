#pragma once
/// \file
/// The numbers of the interior inspection that users choose: the X-ray values of
/// TransparencySettings and the cap pattern's spacing, for `trimlab render` and the
/// Render panel alike (core/util/parameter_spec.h). Defaults are TransparencySettings'
/// own; the spacing is a fraction of the scene's bounding radius, so that the pattern
/// looks alike on any scene (CapSettings::spacing = fraction × radius of the scene shown).

#include "core/trim/inspect_settings.h"
#include "core/util/parameter_spec.h"

#include <array>

namespace trimlab::inspect_parameters {

inline constexpr ParameterSpec kLayerAlpha{
    .id = "layer-alpha",
    .flag = "layer-alpha",
    .settingsKey = "render/xrayLayerAlpha",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1.0,
    .defaultValue = TransparencySettings{}.layerAlpha,
    .help = "X-ray: opacity of each layer of the trimmed solid with translucent transparency",
    .decimals = 2,
    .step = 0.05,
};

inline constexpr ParameterSpec kGhostAlpha{
    .id = "ghost-alpha",
    .flag = "ghost-alpha",
    .settingsKey = "render/xrayGhostAlpha",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1.0,
    .defaultValue = TransparencySettings{}.ghostAlpha,
    .help = "X-ray: opacity of each fragment the trim removed",
    .minMeaning = "hidden",
    .decimals = 2,
    .step = 0.05,
};

/// 0–1000: absorption per world unit, so a scene in small units (a radius of 0.01) needs
/// large values; beyond 1000 the first millimetre of a metre-sized scene is black.
inline constexpr ParameterSpec kDensity{
    .id = "density",
    .flag = "density",
    .settingsKey = "render/xrayDensity",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 1000.0,
    .defaultValue = TransparencySettings{}.density,
    .help = "X-ray: absorption per world unit of distance travelled inside the solid (Beer-Lambert)",
    .minMeaning = "none",
    .decimals = 3,
    .step = 0.1,
};

/// 0–16: a layer's alpha is a + (1 − a)(1 − |n·v|)^P; at P = 16 only grazing angles change,
/// larger exponents change nothing visible.
inline constexpr ParameterSpec kFresnel{
    .id = "fresnel",
    .flag = "fresnel",
    .settingsKey = "render/xrayFresnel",
    .kind = ParameterKind::Real,
    .min = 0.0,
    .max = 16.0,
    .defaultValue = TransparencySettings{}.fresnelExponent,
    .help = "X-ray: Fresnel exponent P, layers grow more opaque towards grazing angles, a + (1 - a)(1 - |n.v|)^P",
    .minMeaning = "off",
    .decimals = 2,
    .step = 0.5,
};

inline constexpr ParameterSpec kCapSpacing{
    .id = "cap-spacing",
    .flag = "cap-spacing",
    .settingsKey = "render/capSpacingFraction",
    .kind = ParameterKind::Real,
    .min = 0.001,
    .max = 1.0,
    .defaultValue = 1.0 / 25.0,
    .help = "Distance between neighbouring lines of the cap pattern, as a fraction of the scene's bounding radius",
    .decimals = 3,
    .step = 0.005,
};

inline constexpr std::array<const ParameterSpec*, 5> kTable{&kLayerAlpha, &kGhostAlpha, &kDensity, &kFresnel,
                                                            &kCapSpacing};
static_assert(isWellFormedTable(kTable));

} // namespace trimlab::inspect_parameters
