#pragma once
/// \file
/// What a renderer needs to show frame f of a Timeline: the frame as a plain scene (the
/// static rules) or the chain of reference frames to it (the dynamic rules). Shared by
/// the GUI and `trimlab render --script/--frame`.

#include "core/scene/scene.h"
#include "core/timeline/timeline.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/static_rule.h"

#include <glm/mat4x4.hpp>

#include <string>

namespace trimlab::timeline {

/// Frame f as a one-object scene with model matrix `model` (0 <= f < frameCount()).
[[nodiscard]] Scene frameScene(const Timeline& timeline, int f, const glm::dmat4& model = glm::dmat4(1.0),
                               const std::string& name = "frame");

/// The dynamic chain to frame f (Timeline::chainTo): every set's reference frame, then f;
/// the base mesh classified by `baseRule`.
[[nodiscard]] DynamicChain frameChain(const Timeline& timeline, int f, StaticRule baseRule,
                                      const glm::dmat4& model = glm::dmat4(1.0));

/// World bounds of everything the chain rasterises (all its levels), which the camera's
/// depth range must enclose: the winding indices are counted from the far side.
[[nodiscard]] Bounds chainBounds(const DynamicChain& chain);

/// Object-space bounds of every frame of `history`: the base mesh and every position a
/// frame moved to — what a view of the whole history must enclose.
[[nodiscard]] Bounds historyBounds(const Timeline& history);

} // namespace trimlab::timeline
