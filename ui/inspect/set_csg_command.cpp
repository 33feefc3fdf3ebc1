#include "ui/inspect/set_csg_command.h"

#include "ui/inspect/inspect_scene.h"

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
    : InspectSceneValueCommand(scene, before, after, typingSession)
{
    setText(undoTexts(text));
}

void SetCsgCommand::apply(const CsgSettings& csg)
{
    m_scene.applyCsg(csg);
}

bool SetCsgCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetCsgCommand*>(other); // same id(): same type
    if (!sameSession(*next))
        return false;
    takeAfter(*next);
    setText(undoTexts(next->text()));
    return true;
}

} // namespace trimlab::ui
