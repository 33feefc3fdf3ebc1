#pragma once
/// \file
/// Help ▸ Keyboard Shortcuts and Help ▸ User Guide. The shortcuts are read from the
/// window's menus when asked (so the list cannot drift from the actions), followed by
/// the mouse in the view; the guide is a short tour of the main tasks with the names of
/// the documents in docs/ that go deeper.

class QMainWindow;
class QWidget;

namespace trimlab::ui {

/// A dialog listing every menu action that has a shortcut (menu, action, keys) and what
/// the mouse does in the view.
void showKeyboardShortcuts(QMainWindow& window);
/// A dialog with the user guide.
void showUserGuide(QWidget* parent);

} // namespace trimlab::ui
