#pragma once
/// \file
/// How the Timeline classifies the poses it plays: each pose alone under the Render
/// panel's static rule, or the animation as a deformation history (thesis 8.1) whose
/// frames are its poses, every pose classified by a dynamic rule against the rest pose or
/// against the previous pose (the classification carried from pose to pose). The
/// Render panel's static rule classifies the rest pose either way.

#include "core/animation/animation_chain.h"
#include "core/trim/dynamic_rule.h"

#include <optional>

namespace trimlab::ui {

struct PoseHistoryChoices {
    /// nullopt: every pose alone, under the static rule (what a first-time user expects of
    /// a player: the pose as it is).
    std::optional<DynamicRule> rule;
    /// The thesis's choice for animations: each pose a set against the one before.
    PoseReference reference = PoseReference::Previous;

    friend bool operator==(const PoseHistoryChoices&, const PoseHistoryChoices&) = default;
};

} // namespace trimlab::ui
