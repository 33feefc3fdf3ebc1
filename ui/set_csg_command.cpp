#include "set_csg_command.h"

#include "inspect_scene.h"

namespace trimlab::ui {

namespace {

/// `text` for the undo view and, with '&' doubled, for the Edit menu's action text ("1 & 2"
/// would otherwise turn into a mnemonic): QUndoCommand splits the two at the newline.
QString undoTexts(const QString& text)
{
    return text + QLatin1Char('\n') + QString(text).replace(QLatin1Char('&'), QStringLiteral("&&"));
}

} // namespace

SetCsgCommand::SetCsgCommand(InspectScene& scene, const CsgSettings& before, const CsgSettings& after,
                             const QString& text, int typingSession)
    : m_scene(scene), m_before(before), m_after(after), m_typingSession(typingSession)
{
    setText(undoTexts(text));
}

void SetCsgCommand::redo()
{
    m_scene.applyCsg(m_after);
}

void SetCsgCommand::undo()
{
    m_scene.applyCsg(m_before);
}

bool SetCsgCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetCsgCommand*>(other); // same id(): same type
    if (m_typingSession < 0 || next->m_typingSession != m_typingSession)
        return false;
    m_after = next->m_after;
    setText(undoTexts(next->text()));
    return true;
}

} // namespace trimlab::ui
