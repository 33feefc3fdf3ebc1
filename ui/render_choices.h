#pragma once
/// \file
/// What the user chose in the Render panel: the trim settings shared with the renderers
/// and the k⁺-buffer capacity. The GUI persists it (render_settings_store.h).

#include "trim/trim_settings.h"

namespace trimlab::ui {

struct RenderChoices {
    TrimSettings trim;
    /// k⁺-buffer capacity per pixel, 1..MethodParameters::kMaxK (TrimRenderer's default).
    int k = 16;
};

/// What a new user sees first: the alternating border rule, and a clipping plane
/// n = (0, 0, −1), offset 0 that removes the half of a demo scene (centred at the origin)
/// facing fitCamera's default view, so the trimmed interior is visible at once.
[[nodiscard]] inline RenderChoices firstStartRenderChoices()
{
    RenderChoices choices;
    choices.trim.trimEnabled = true;
    choices.trim.rule = StaticRule::AlternatingBorder;
    choices.trim.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    return choices;
}

} // namespace trimlab::ui
