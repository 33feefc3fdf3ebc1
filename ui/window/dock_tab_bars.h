#pragma once
/// \file
/// The tab bars of the main window's tabbed docks show whole titles: QMainWindow creates
/// them itself, eliding titles to fit ("Re…", "Segmenta…"), and offers no setting for it.
/// Each tab bar it adds is set not to elide and to scroll (arrow buttons) when its tabs
/// do not fit, so a title is never cut, only scrolled out of sight.

class QMainWindow;

namespace trimlab::ui {

/// Watches `window` for the tab bars it creates for tabbed docks and keeps their titles
/// whole from then on.
void keepDockTabTitlesWhole(QMainWindow& window);

} // namespace trimlab::ui
