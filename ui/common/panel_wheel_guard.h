#pragma once
/// \file
/// The mouse wheel over a side panel scrolls the panel; it changes a spin box, combo box or
/// slider only once the user has given that control the focus (clicked or tabbed into it).
/// Qt's default gives these controls the focus on a wheel turn and changes their value, so
/// scrolling a long panel changed whatever control passed under the cursor (k went from
/// 16 to 13) and re-rendered.

class QScrollArea;

namespace trimlab::ui {

/// Makes the wheel scroll `panel` unless the control under the cursor has the focus:
/// such controls stop taking the focus from the wheel (Qt::StrongFocus), and one
/// application-wide filter (installed on the first call) sends their wheel events to the
/// panel's scroll bar instead.
void guardPanelWheel(QScrollArea& panel);

} // namespace trimlab::ui
