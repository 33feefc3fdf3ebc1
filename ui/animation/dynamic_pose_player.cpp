#include "ui/animation/dynamic_pose_player.h"

#include "ui/viewport/viewport_widget.h"

#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_frame_scene.h"

namespace trimlab::ui {

void DynamicPosePlayer::setAnimation(std::shared_ptr<const MeshAnimation> animation, PosePositions positions)
{
    m_animation = std::move(animation);
    m_positions = std::move(positions);
    m_shownPose.reset();
    m_chainShown = false; // the viewport dropped any chain with the previous scene
}

void DynamicPosePlayer::setChoices(const PoseHistoryChoices& choices, StaticRule baseRule)
{
    m_choices = choices;
    m_baseRule = baseRule;
    m_shownPose.reset();
}

void DynamicPosePlayer::stop()
{
    if (m_chainShown)
        m_viewport->setDynamicChain(nullptr);
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
        m_viewport->showPose(m_positions(pose));
        m_shownPose = pose;
        return true;
    }
    if (canAppend(pose))
        appendSteps(pose);
    else
        showWholeChain(pose);
    m_shownPose = pose;
    return true;
}

// Against the previous pose, a pose further from the rest pose on the side of the one
// shown extends its history; the rest pose itself has no chain to extend.
bool DynamicPosePlayer::canAppend(std::size_t pose) const
{
    if (m_choices.reference != PoseReference::Previous || !m_chainShown || !m_shownPose)
        return false;
    const std::size_t rest = m_animation->restPose;
    const std::size_t shown = *m_shownPose;
    return (shown > rest && pose > shown) || (shown < rest && pose < shown);
}

void DynamicPosePlayer::appendSteps(std::size_t pose)
{
    const std::size_t shown = *m_shownPose;
    const bool forward = pose > shown;
    std::vector<glm::vec3> previous = m_positions(shown);
    for (std::size_t p = forward ? shown + 1 : shown - 1;; p = forward ? p + 1 : p - 1) {
        std::vector<glm::vec3> current = m_positions(p);
        m_viewport->appendDynamicLevel(std::make_shared<const DynamicChainLevel>(
            DynamicChainLevel{makeDynamicFrameScene(m_animation->triangles, previous, current), *m_choices.rule}));
        if (p == pose)
            break;
        previous = std::move(current);
    }
}

void DynamicPosePlayer::showWholeChain(std::size_t pose)
{
    std::vector<std::vector<glm::vec3>> frames;
    for (std::size_t p : chainPoses(m_animation->restPose, pose, m_choices.reference))
        frames.push_back(m_positions(p));
    const std::vector<DynamicRule> rules(frames.size() - 1, *m_choices.rule);
    m_viewport->setDynamicChain(
        std::make_shared<const DynamicChain>(makeDynamicChain(m_animation->triangles, frames, rules, m_baseRule)));
    m_chainShown = true;
}

} // namespace trimlab::ui
