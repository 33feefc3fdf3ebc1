#pragma once
/// \file
/// One pose edit of the Skinning panel as an undoable command: it holds the model before
/// and after (both immutable and shared) and shows one or the other in its session.

#include <QUndoCommand>

#include <memory>

namespace trimlab {
struct SkinningModel;
}

namespace trimlab::ui {

class SkinningSession;

class SkinningEditCommand : public QUndoCommand {
public:
    /// `session` must outlive the command (it owns the stack the command is pushed on).
    SkinningEditCommand(SkinningSession* session, std::shared_ptr<const SkinningModel> before,
                        std::shared_ptr<const SkinningModel> after, const QString& text);

    void undo() override;
    void redo() override;

private:
    SkinningSession* m_session;
    std::shared_ptr<const SkinningModel> m_before;
    std::shared_ptr<const SkinningModel> m_after;
};

} // namespace trimlab::ui
