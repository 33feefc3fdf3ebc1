#include "ui/animation/dynamic_pose_player.h"

#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_frame_scene.h"

namespace trimlab::ui {

void DynamicPosePlayer::setAnimation(std::shared_ptr<const MeshAnimation> animation, PosePositions positions)
{
    m_animation = std::move(animation);
    m_positions = std::move(positions);
    m_shownPose.reset();
    m_chainShown = false; // the content dropped any chain with the previous scene
    updateHistory();
}

void DynamicPosePlayer::setChoices(const PoseHistoryChoices& choices, StaticRule baseRule)
{
    m_choices = choices;
    m_baseRule = baseRule;
    m_shownPose.reset();
    updateHistory();
}

void DynamicPosePlayer::updateHistory()
{
    m_history = m_animation && m_choices.rule ? referenceHistory(m_animation->restPose, m_animation->poseCount(),
                                                                 m_choices.reference, *m_choices.rule)
                                              : PoseHistorySets{};
}

void DynamicPosePlayer::stop()
{
    if (m_chainShown)
        m_shown.showChain(nullptr);
    m_chainShown = false;
    m_shownPose.reset();
}

bool DynamicPosePlayer::show(std::size_t pose)
{
    if (!m_animation || !m_choices.rule || pose >= m_animation->poseCount()) {
        stop();
        return false;
    }
    if (pose == m_animation->restPose) {
        stop(); // nothing has deformed yet: the static rule alone classifies it
        m_shownPose = pose;
        return true;
    }
    const PoseHistoryStep step = planPoseHistory(m_history, m_chainShown ? m_shownPose : std::nullopt, pose);
    switch (step.kind) {
    case PoseHistoryStep::Kind::Append:
        appendSteps(step.levels);
        break;
    case PoseHistoryStep::Kind::ReplaceShown:
        replaceShownLevel(step.levels.back());
        break;
    case PoseHistoryStep::Kind::New:
        showWholeChain(step.levels);
        break;
    }
    m_shownPose = pose;
    return true;
}

// Each level's reference is the pose the level before ended at: its positions carry over.
void DynamicPosePlayer::appendSteps(const std::vector<PoseHistoryLevel>& levels)
{
    std::vector<glm::vec3> previous = m_positions(levels.front().reference);
    for (const PoseHistoryLevel& level : levels) {
        std::vector<glm::vec3> current = m_positions(level.pose);
        m_shown.appendLevel(std::make_shared<const DynamicChainLevel>(
            DynamicChainLevel{makeDynamicFrameScene(m_animation->triangles, previous, current), *m_choices.rule}));
        previous = std::move(current);
    }
}

void DynamicPosePlayer::replaceShownLevel(const PoseHistoryLevel& level)
{
    const std::vector<glm::vec3> reference = m_positions(level.reference);
    const std::vector<glm::vec3> current = m_positions(level.pose);
    m_shown.replaceShownLevel(std::make_shared<const DynamicChainLevel>(
        DynamicChainLevel{makeDynamicFrameScene(m_animation->triangles, reference, current), *m_choices.rule}));
}

void DynamicPosePlayer::showWholeChain(const std::vector<PoseHistoryLevel>& levels)
{
    std::vector<std::vector<glm::vec3>> frames{m_positions(levels.front().reference)};
    for (const PoseHistoryLevel& level : levels)
        frames.push_back(m_positions(level.pose));
    const std::vector<DynamicRule> rules(frames.size() - 1, *m_choices.rule);
    m_shown.showChain(
        std::make_shared<const DynamicChain>(makeDynamicChain(m_animation->triangles, frames, rules, m_baseRule)));
    m_chainShown = true;
}

} // namespace trimlab::ui
