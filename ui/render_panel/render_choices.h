#pragma once
/// \file
/// What the user chose in the Render panel: the trim settings shared with the renderers,
/// the multi-fragment method and its parameters. The GUI persists it
/// (render_settings_store.h).

#include "core/trim/inspect_parameters.h"
#include "core/trim/trim_settings.h"
#include "render/mfr/fragment_method.h"
#include "render/mfr/method_parameter_table.h"

#include <cstddef>

namespace trimlab::ui {

struct RenderChoices {
    TrimSettings trim;
    /// The multi-fragment method (one of render::fragmentMethods()).
    render::FragmentMethodKind method = render::FragmentMethodKind::KPlusArray;
    /// k, S and the GPU memory budget in MB (0: none); their ranges and defaults are the rows
    /// of render/mfr/method_parameter_table.h.
    int k = render::MethodParameters{}.k;
    int sharedCounters = render::MethodParameters{}.sharedCounters;
    int memoryBudgetMegabytes = int(render::method_parameters::kMemoryBudget.defaultValue);
    /// Classification of a designer session's frames: false, the static rule of `trim`
    /// alone; true, the dynamic rules of the history's sets (thesis 8.1.1), with the
    /// static rule classifying the base mesh.
    bool dynamicRules = false;
    /// The cap pattern's line spacing as a fraction of the scene's bounding radius
    /// (inspect_parameters::kCapSpacing); trim.cap.spacing is this times the radius of the
    /// scene shown (RenderPanel::renderChoices), so the pattern looks alike on any scene.
    double capSpacingFraction = inspect_parameters::kCapSpacing.defaultValue;

    /// The renderer's parameters for these choices (the others at their defaults).
    [[nodiscard]] render::MethodParameters methodParameters() const
    {
        render::MethodParameters parameters;
        parameters.k = k;
        parameters.sharedCounters = sharedCounters;
        parameters.memoryBudgetBytes = render::method_parameters::budgetBytes(memoryBudgetMegabytes);
        return parameters;
    }

    friend bool operator==(const RenderChoices&, const RenderChoices&) = default;
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
