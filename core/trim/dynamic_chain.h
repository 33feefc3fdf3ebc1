#pragma once
/// \file
/// Everything needed to show one frame under the dynamic rules: the chain of sets from
/// the base mesh to the current frame (thesis 8.1.2). Level j rasterises reference frame
/// V_j against V_(j+1) (the reference of the next set, i.e. the last frame of set j+1);
/// the last level rasterises the current set's reference against the shown frame.
/// The first level's reference is the base mesh, classified by a static rule; every later
/// level's reference classification is the characterization the level before produced.

#include "core/trim/dynamic_frame_scene.h"
#include "core/trim/dynamic_rule.h"
#include "core/trim/static_rule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace trimlab {

struct DynamicChainLevel {
    DynamicFrameScene frame;
    DynamicRule rule = DynamicRule::Confluent;
};

struct DynamicChain {
    StaticRule baseRule = StaticRule::AlternatingBorder; ///< classification of the base mesh
    std::vector<DynamicChainLevel> levels;               ///< at least one; the last is shown
};

/// Builds the chain from the frames' positions: `frames` = V_0 (base), V_1, ...,
/// V_(k−1) (the references of sets 1..k−1 after the first), then the shown frame;
/// `rules[j]` is the rule of the set whose reference is frames[j]. Requires
/// frames.size() == rules.size() + 1 >= 2 (std::invalid_argument otherwise).
[[nodiscard]] DynamicChain makeDynamicChain(const std::vector<glm::uvec3>& triangles,
                                            const std::vector<std::vector<glm::vec3>>& frames,
                                            const std::vector<DynamicRule>& rules, StaticRule baseRule,
                                            const glm::dmat4& modelMatrix = glm::dmat4(1.0));

} // namespace trimlab
