#pragma once
/// \file
/// Undo command of changing the CSG settings of the scene shown: the expression (typed or
/// built in the Scene panel) or one object's rule. Commands made while typing one
/// expression merge (InspectScene::editCsg).

#include "ui/inspect/inspect_scene_value_command.h"
#include "core/trim/inspect_settings.h"

namespace trimlab::ui {

/// kId 0x6373: QUndoCommand::id(), the merge key of this command type.
class SetCsgCommand : public InspectSceneValueCommand<CsgSettings, 0x6373> {
public:
    /// `typingSession` >= 0 lets the command merge with the next one of the same session;
    /// −1 never merges.
    SetCsgCommand(InspectScene& scene, const CsgSettings& before, const CsgSettings& after, const QString& text,
                  int typingSession);

    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const CsgSettings& csg) override;
};

} // namespace trimlab::ui
