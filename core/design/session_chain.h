#pragma once
/// \file
/// The dynamic-rule chain (trim/dynamic_chain.h) that shows one frame of a deformation
/// history: the reference frames of every set up to the frame's, oldest first, then the
/// frame itself. The base mesh is classified by the static rule.

#include "core/timeline/timeline.h"
#include "core/trim/dynamic_chain.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace trimlab {

/// The chain of Timeline::chainTo(frame) with every reference's positions and `frame`'s
/// (`shown`, when given, replaces frame's positions: a drag in progress).
[[nodiscard]] DynamicChain dynamicChainTo(const timeline::Timeline& history, int frame, StaticRule baseRule,
                                          const glm::dmat4& model);

/// The shown level of a chain whose last reference is `reference` under `rule`, with the
/// shown frame at `current`: what a drag replaces on every mouse move.
[[nodiscard]] DynamicChainLevel dynamicShownLevel(const timeline::Timeline& history,
                                                  const std::vector<glm::vec3>& reference,
                                                  const std::vector<glm::vec3>& current, DynamicRule rule,
                                                  const glm::dmat4& model);

} // namespace trimlab
