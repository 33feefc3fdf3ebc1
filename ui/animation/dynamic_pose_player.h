#pragma once
/// \file
/// Shows the poses of a mesh animation under a dynamic rule
/// (pose_history_choices.h; thesis 8.1): the animation is a deformation history whose
/// frames are its poses. Against the rest pose every pose is one set, one level. Against
/// the previous pose the chain of the pose shown has a set per pose from the rest pose;
/// going further from the rest pose (playing forward, even with poses dropped to keep
/// time) appends the steps to the chain shown, so each frame characterizes only the
/// new sets and the classification is carried from pose to pose (Algorithms 8.11–8.13);
/// against the rest pose, another pose on the same side replaces only the shown level.
/// Anything else (scrubbing back, a jump over the rest pose, another choice) builds the
/// chain from the rest pose. Which of the three a pose takes is the core's plan
/// (core/animation/pose_history_plan.h), the one `trimlab render --poses` follows too.
/// All give the same picture: the GPU characterizes the same levels either way. The chain
/// is published as animation playback's (render/content_publisher.h); the pose itself is
/// the animation workspace's to publish.

#include "ui/animation/pose_history_choices.h"

#include "render/content_publisher.h"

#include "core/animation/mesh_animation.h"
#include "core/animation/pose_history_plan.h"
#include "core/trim/static_rule.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace trimlab::ui {

class DynamicPosePlayer {
public:
    /// The positions of a pose as shown: the captured pose, or its skinned approximation.
    using PosePositions = std::function<std::vector<glm::vec3>(std::size_t pose)>;

    /// Publishes its chains through `shown`.
    explicit DynamicPosePlayer(render::ContentPublisher shown) : m_shown(std::move(shown)) {}

    /// The animation whose poses are shown (nullptr: none) and where their positions come
    /// from. Forgets the chain shown.
    void setAnimation(std::shared_ptr<const MeshAnimation> animation, PosePositions positions);
    /// Forgets the chain shown, so that the next show() builds it again.
    void setChoices(const PoseHistoryChoices& choices, StaticRule baseRule);
    /// The positions of the poses changed (another approximation shown): the next show()
    /// builds the chain again.
    void invalidate() { m_shownPose.reset(); }

    /// Shows the chain of `pose` under the dynamic rule and returns true; false (no chain)
    /// under the static rule or without an animation. The rest pose, which nothing has
    /// deformed yet, is shown by its static rule, without a chain (true).
    bool show(std::size_t pose);
    /// Back to the static rule (withdraws the chain) if a chain is shown.
    void stop();

    [[nodiscard]] const PoseHistoryChoices& choices() const { return m_choices; }

private:
    void updateHistory();
    void showWholeChain(const std::vector<PoseHistoryLevel>& levels);
    void appendSteps(const std::vector<PoseHistoryLevel>& levels);
    void replaceShownLevel(const PoseHistoryLevel& level);

    render::ContentPublisher m_shown;
    std::shared_ptr<const MeshAnimation> m_animation;
    PosePositions m_positions;
    PoseHistoryChoices m_choices;
    StaticRule m_baseRule = StaticRule::AlternatingBorder;
    PoseHistorySets m_history;              ///< the sets of m_choices over m_animation
    std::optional<std::size_t> m_shownPose; ///< the pose whose chain is published
    bool m_chainShown = false;              ///< a chain of ours is published
};

} // namespace trimlab::ui
