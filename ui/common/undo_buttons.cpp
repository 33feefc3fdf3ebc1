#include "ui/common/undo_buttons.h"

#include <QKeyEvent>
#include <QPushButton>
#include <QUndoStack>

namespace trimlab::ui {

namespace {

bool isUndoKey(const QKeyEvent& key)
{
    return key.matches(QKeySequence::Undo);
}

bool isRedoKey(const QKeyEvent& key)
{
    return key.matches(QKeySequence::Redo) ||
           key.keyCombination() == QKeyCombination(Qt::ControlModifier | Qt::ShiftModifier, Qt::Key_Z);
}

} // namespace

UndoButtons::UndoButtons(const QString& undoName, const QString& redoName, QObject* parent)
    : QObject(parent), m_undo(new QPushButton(tr("Undo"))), m_redo(new QPushButton(tr("Redo")))
{
    m_undo->setObjectName(undoName);
    m_redo->setObjectName(redoName);
    connect(m_undo, &QPushButton::clicked, this, [this] {
        if (m_stack)
            m_stack->undo();
    });
    connect(m_redo, &QPushButton::clicked, this, [this] {
        if (m_stack)
            m_stack->redo();
    });
    update();
}

void UndoButtons::setStack(QUndoStack* stack)
{
    if (m_stack)
        disconnect(m_stack, nullptr, this, nullptr);
    m_stack = stack;
    if (m_stack) {
        connect(m_stack, &QUndoStack::canUndoChanged, this, &UndoButtons::update);
        connect(m_stack, &QUndoStack::canRedoChanged, this, &UndoButtons::update);
        connect(m_stack, &QUndoStack::undoTextChanged, this, &UndoButtons::update);
        connect(m_stack, &QUndoStack::redoTextChanged, this, &UndoButtons::update);
    }
    update();
}

void UndoButtons::update()
{
    if (!m_undo || !m_redo)
        return;
    const bool canUndo = m_stack && m_stack->canUndo();
    const bool canRedo = m_stack && m_stack->canRedo();
    m_undo->setEnabled(canUndo);
    m_redo->setEnabled(canRedo);
    m_undo->setToolTip(canUndo ? tr("Undo %1 (Ctrl+Z)").arg(m_stack->undoText()) : QString());
    m_redo->setToolTip(canRedo ? tr("Redo %1 (Ctrl+Shift+Z)").arg(m_stack->redoText()) : QString());
}

bool isUndoOrRedoKey(const QKeyEvent& key)
{
    return isUndoKey(key) || isRedoKey(key);
}

bool applyUndoKey(QUndoStack& stack, const QKeyEvent& key)
{
    if (isUndoKey(key)) {
        stack.undo();
        return true;
    }
    if (isRedoKey(key)) {
        stack.redo();
        return true;
    }
    return false;
}

} // namespace trimlab::ui
