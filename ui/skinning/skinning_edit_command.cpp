#include "ui/skinning/skinning_edit_command.h"

#include "ui/skinning/skinning_session.h"

namespace trimlab::ui {

SkinningEditCommand::SkinningEditCommand(SkinningSession* session, std::shared_ptr<const SkinningModel> before,
                                         std::shared_ptr<const SkinningModel> after, const QString& text)
    : QUndoCommand(text), m_session(session), m_before(std::move(before)), m_after(std::move(after))
{
}

void SkinningEditCommand::undo()
{
    m_session->setModel(m_before);
}

void SkinningEditCommand::redo()
{
    m_session->setModel(m_after);
}

} // namespace trimlab::ui
