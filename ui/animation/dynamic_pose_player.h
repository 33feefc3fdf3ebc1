#pragma once
/// \file
/// Shows the poses of a mesh animation in the viewport under a dynamic rule
/// (pose_history_choices.h; thesis 8.1): the animation is a deformation history whose
/// frames are its poses. Against the rest pose every pose is one set, one level. Against
/// the previous pose the chain of the pose shown has a set per pose from the rest pose;
/// going further from the rest pose (playing forward, even with poses dropped to keep
/// time) appends the steps to the viewport's chain, so each frame characterizes only the
/// new sets and the classification is carried from pose to pose (Algorithms 8.11–8.13).
/// Anything else (scrubbing back, a jump over the rest pose, another choice) builds the
/// chain from the rest pose. Both give the same picture: the GPU characterizes the same
/// levels either way.

#include "ui/animation/pose_history_choices.h"

#include "core/animation/mesh_animation.h"
#include "core/trim/static_rule.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab::ui {

class ViewportWidget;

class DynamicPosePlayer {
public:
    /// The positions of a pose as shown: the captured pose, or its skinned approximation.
    using PosePositions = std::function<std::vector<glm::vec3>(std::size_t pose)>;

    explicit DynamicPosePlayer(ViewportWidget* viewport) : m_viewport(viewport) {}

    /// The animation whose poses are shown (nullptr: none) and where their positions come
    /// from. Forgets the chain shown.
    void setAnimation(std::shared_ptr<const MeshAnimation> animation, PosePositions positions);
    /// Forgets the chain shown, so that the next show() builds it again.
    void setChoices(const PoseHistoryChoices& choices, StaticRule baseRule);
    /// The positions of the poses changed (another approximation shown): the next show()
    /// builds the chain again.
    void invalidate() { m_shownPose.reset(); }

    /// Shows `pose` under the dynamic rule and returns true; false (nothing done) under
    /// the static rule or without an animation: the caller shows the pose as it is.
    /// The rest pose, which nothing has deformed yet, is shown by its static rule, without
    /// a chain.
    bool show(std::size_t pose);
    /// Back to the static rule (drops the viewport's chain) if a chain is shown.
    void stop();

    [[nodiscard]] const PoseHistoryChoices& choices() const { return m_choices; }

private:
    void showWholeChain(std::size_t pose);
    void appendSteps(std::size_t pose);
    [[nodiscard]] bool canAppend(std::size_t pose) const;

    ViewportWidget* m_viewport;
    std::shared_ptr<const MeshAnimation> m_animation;
    PosePositions m_positions;
    PoseHistoryChoices m_choices;
    StaticRule m_baseRule = StaticRule::AlternatingBorder;
    std::optional<std::size_t> m_shownPose; ///< the pose whose chain the viewport holds
    bool m_chainShown = false;              ///< the viewport renders a chain of ours
};

} // namespace trimlab::ui
