#pragma once
/// \file
/// Undo command of moving one scene object (the Scene panel's transform fields).
/// Consecutive commands that change the same single component (say, rotation about y)
/// of the same object merge, so that stepping a spin box is one undo step; so do the
/// commands of one drag in the viewport (the same drag session).

#include "ui/inspect/inspect_scene_value_command.h"
#include "core/scene/object_transform.h"

namespace trimlab::ui {

/// kId 0x7472: QUndoCommand::id(), the merge key of this command type.
class SetObjectTransformCommand : public InspectSceneValueCommand<ObjectTransform, 0x7472> {
public:
    /// `dragSession` >= 0: a step of that drag, merging with the drag's next steps; −1:
    /// a field edit, merging by component.
    SetObjectTransformCommand(InspectScene& scene, int object, const ObjectTransform& before,
                              const ObjectTransform& after, int dragSession = -1);

    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const ObjectTransform& transform) override;

    int m_object;
    int m_component; ///< the one component (0..6: tx ty tz rx ry rz scale) changed, else −1
};

/// The component (0..6: translation x, y, z, rotation x, y, z, scale) in which `a` and `b`
/// differ when they differ in exactly one; −1 otherwise.
[[nodiscard]] int changedTransformComponent(const ObjectTransform& a, const ObjectTransform& b);

} // namespace trimlab::ui
