#pragma once
/// \file
/// The Brush panel's choices and the brush tool toggle in a QSettings (keys "brush/…").
/// The radius is stored as a fraction of the mesh's bounding radius, not in mesh units:
/// meshes come in any units, and a radius that suits one would cover all or nothing of
/// another. Missing or unusable values fall back field by field to BrushChoices' defaults.

#include "core/deform/stroke.h"

class QSettings;

namespace trimlab::ui {

struct BrushChoices {
    /// Brush radius / bounding radius of the base mesh, in (0, kMaxRadiusFraction].
    double radiusFraction = 0.15;
    /// Everything but the radius (which follows from radiusFraction per mesh).
    deform::BrushSettings settings;
    bool toolEnabled = false;

    static constexpr double kMinRadiusFraction = 0.005;
    static constexpr double kMaxRadiusFraction = 2.0;
    static constexpr int kMaxIterations = 50;
    static constexpr double kMaxStrength = 5.0;
};

[[nodiscard]] BrushChoices loadBrushChoices(const QSettings& settings);
void saveBrushChoices(QSettings& settings, const BrushChoices& choices);

} // namespace trimlab::ui
