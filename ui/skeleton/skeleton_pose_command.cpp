#include "ui/skeleton/skeleton_pose_command.h"

#include <utility>

namespace trimlab::ui {

namespace {

constexpr int kSkeletonPoseCommandId = 0x5e1e;

} // namespace

SkeletonPoseCommand::SkeletonPoseCommand(const QString& text, SkeletonPose before, SkeletonPose after, int bone,
                                         int gesture, bool fromAngleBoxes, ApplySkeletonPose apply)
    : QUndoCommand(text),
      m_before(std::move(before)),
      m_after(std::move(after)),
      m_bone(bone),
      m_gesture(gesture),
      m_keepAnglesOnce(fromAngleBoxes),
      m_apply(std::move(apply))
{
}

void SkeletonPoseCommand::undo()
{
    m_apply(m_before, m_bone, true);
}

void SkeletonPoseCommand::redo()
{
    m_apply(m_after, m_bone, !m_keepAnglesOnce);
    m_keepAnglesOnce = false;
}

int SkeletonPoseCommand::id() const
{
    return m_gesture < 0 ? -1 : kSkeletonPoseCommandId;
}

bool SkeletonPoseCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SkeletonPoseCommand*>(other);
    if (next->m_gesture != m_gesture || next->m_bone != m_bone)
        return false;
    m_after = next->m_after;
    return true;
}

} // namespace trimlab::ui
