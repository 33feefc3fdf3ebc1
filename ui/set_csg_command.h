#pragma once
/// \file
/// Undo command of changing the CSG settings of the scene shown: the expression (typed or
/// built in the Scene panel) or one object's rule. Commands made while typing one
/// expression merge (InspectScene::editCsg).

#include "trim/inspect_settings.h"

#include <QUndoCommand>

namespace trimlab::ui {

class InspectScene;

class SetCsgCommand : public QUndoCommand {
public:
    static constexpr int kId = 0x6373; // QUndoCommand::id(): merge key of this command type

    /// `typingSession` >= 0 lets the command merge with the next one of the same session;
    /// −1 never merges.
    SetCsgCommand(InspectScene& scene, const CsgSettings& before, const CsgSettings& after, const QString& text,
                  int typingSession);

    void redo() override;
    void undo() override;
    [[nodiscard]] int id() const override { return kId; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    InspectScene& m_scene;
    CsgSettings m_before;
    CsgSettings m_after;
    int m_typingSession;
};

} // namespace trimlab::ui
