#pragma once
/// \file
/// One undoable change of the Skeleton panel's pose: the whole pose before and after
/// (a few dozen quaternions, so no diffing), and the bone it turned (selected again on
/// undo and redo, so the spin boxes show what changed back).
///
/// A gesture — one mouse drag, or consecutive edits of one spin box of one bone — is one
/// step: commands with the same non-negative gesture merge, keeping the first `before`
/// and the last `after`. A gesture of −1 never merges (Reset pose).

#include "core/skeleton/skeleton_pose.h"

#include <QUndoCommand>

#include <functional>

namespace trimlab::ui {

/// Shows `pose` with `bone` selected (−1: keep the selection); `refreshAngles` false when
/// the edit came from the angle boxes themselves, which keep the text being typed.
using ApplySkeletonPose = std::function<void(const SkeletonPose& pose, int bone, bool refreshAngles)>;

class SkeletonPoseCommand : public QUndoCommand {
public:
    /// `fromAngleBoxes`: the first redo (on push) leaves the angle boxes as typed.
    SkeletonPoseCommand(const QString& text, SkeletonPose before, SkeletonPose after, int bone, int gesture,
                        bool fromAngleBoxes, ApplySkeletonPose apply);

    void undo() override;
    void redo() override;
    [[nodiscard]] int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    SkeletonPose m_before;
    SkeletonPose m_after;
    int m_bone;
    int m_gesture;
    bool m_keepAnglesOnce;
    ApplySkeletonPose m_apply;
};

} // namespace trimlab::ui
