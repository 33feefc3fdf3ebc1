#pragma once
/// \file
/// What the user chose in the Render panel: the trim settings shared with the renderers,
/// the multi-fragment method and its parameters. The GUI persists it
/// (render_settings_store.h).

#include "render/mfr/fragment_method.h"
#include "core/trim/trim_settings.h"

#include <cstddef>

namespace trimlab::ui {

/// The largest S the GUI and the command line accept.
inline constexpr int kMaxSharedCounters = 1 << 20;
/// The largest GPU memory budget the GUI accepts, in MB (1 TB: no real limit).
inline constexpr int kMaxMemoryBudgetMegabytes = 1 << 20;

struct RenderChoices {
    TrimSettings trim;
    /// The multi-fragment method (one of render::fragmentMethods()).
    render::FragmentMethodKind method = render::FragmentMethodKind::KPlusArray;
    /// Capacity per pixel of the bounded methods, 1..MethodParameters::kMaxK (TrimRenderer's default).
    int k = render::MethodParameters{}.k;
    /// S, the shared counters of the S-buffer family, >= 1.
    int sharedCounters = render::MethodParameters{}.sharedCounters;
    /// GPU memory budget of the method's storage in MB; 0: none (the driver's limits only).
    int memoryBudgetMegabytes = 0;
    /// Classification of a designer session's frames: false, the static rule of `trim`
    /// alone; true, the dynamic rules of the history's sets (thesis 8.1.1), with the
    /// static rule classifying the base mesh.
    bool dynamicRules = false;
    /// The cap pattern's line spacing as a fraction of the scene's bounding radius (the
    /// command line's 1/25 by default); trim.cap.spacing is this times the radius of the
    /// scene shown (RenderPanel::renderChoices), so the pattern looks alike on any scene.
    double capSpacingFraction = kDefaultCapSpacingFraction;

    static constexpr double kDefaultCapSpacingFraction = 1.0 / 25.0;
    /// The range the GUI and the settings store accept for capSpacingFraction.
    static constexpr double kMinCapSpacingFraction = 0.001;
    static constexpr double kMaxCapSpacingFraction = 1.0;

    /// The renderer's parameters for these choices (the others at their defaults).
    [[nodiscard]] render::MethodParameters methodParameters() const
    {
        render::MethodParameters parameters;
        parameters.k = k;
        parameters.sharedCounters = sharedCounters;
        parameters.memoryBudgetBytes = std::size_t(memoryBudgetMegabytes) * 1024 * 1024;
        return parameters;
    }
};

/// What a new user sees first: the alternating border rule on the whole scene. Plane 1
/// is prepared (n = (0, 0, −1), offset 0: it removes the half of a scene centred at the
/// origin that faces fitCamera's default view) but off — a newly opened mesh that
/// appeared cut in half confused first-time users; ticking it shows the interior.
[[nodiscard]] inline RenderChoices firstStartRenderChoices()
{
    RenderChoices choices;
    choices.trim.trimEnabled = true;
    choices.trim.rule = StaticRule::AlternatingBorder;
    choices.trim.clip = ClipPlane{false, {0.0, 0.0, -1.0}, 0.0};
    return choices;
}

} // namespace trimlab::ui
