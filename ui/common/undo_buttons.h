#pragma once
/// \file
/// A panel's own Undo/Redo: two buttons that act on and reflect one QUndoStack (enabled
/// when it can, the command's text in the tooltip), and the keys that reach them from
/// inside the panel. A panel whose edits have their own stack (a skinning session's bone
/// edits, the Skeleton panel's posing) claims Ctrl+Z and Ctrl+Shift+Z while it has focus
/// (isUndoOrRedoKey in the panel's ShortcutOverride), so the window's Edit ▸ Undo of the
/// designer's strokes never undoes a panel edit or the other way round.

#include <QObject>
#include <QPointer>
#include <QPushButton>
#include <QUndoStack>

class QKeyEvent;

namespace trimlab::ui {

class UndoButtons : public QObject {
    Q_OBJECT
public:
    /// Buttons with the given object names (for tests and style sheets); they belong to
    /// whichever layout the caller adds them to.
    UndoButtons(const QString& undoName, const QString& redoName, QObject* parent = nullptr);

    /// The stack the buttons act on and reflect (nullptr: both disabled).
    void setStack(QUndoStack* stack);
    [[nodiscard]] QUndoStack* stack() const { return m_stack; }
    [[nodiscard]] QPushButton* undoButton() const { return m_undo; }
    [[nodiscard]] QPushButton* redoButton() const { return m_redo; }

private:
    void update();

    QPointer<QPushButton> m_undo; ///< owned by the panel's layout, which may go first
    QPointer<QPushButton> m_redo;
    QPointer<QUndoStack> m_stack;
};

/// Whether `key` is the platform's Undo or Redo key, or Ctrl+Shift+Z (for a panel's
/// ShortcutOverride).
[[nodiscard]] bool isUndoOrRedoKey(const QKeyEvent& key);
/// Undoes or redoes on `stack` when `key` is one of those keys; true when it was.
bool applyUndoKey(QUndoStack& stack, const QKeyEvent& key);

} // namespace trimlab::ui
