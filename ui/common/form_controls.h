#pragma once
/// \file
/// Small builders for the controls of the panels and settings forms (segmentation, skinning,
/// skeleton): each control gets its object name (the UI tests and the settings stores
/// find it by that name) and its tool tip in one call.

#include <QList>
#include <QString>

#include <utility>

class QCheckBox;
class QComboBox;
class QLabel;
class QWidget;

namespace trimlab::ui {

/// A combo box named `name` holding `items` (text, data) in order, the first current.
[[nodiscard]] QComboBox* namedComboBox(const char* name, const QList<std::pair<QString, int>>& items,
                                       const QString& toolTip);
/// Makes the item whose data is `value` current; keeps the current item when none has it.
void selectItemWithData(QComboBox* box, int value);
/// A check box named `name`.
[[nodiscard]] QCheckBox* namedCheckBox(const QString& text, const char* name, const QString& toolTip);

/// How serious a notice label is: a warning (orange: something does not apply now) or an
/// error (red: the input is refused).
enum class NoticeKind { Warning, Error };
/// A hidden, word-wrapped label named `name` that says why something does not apply, in
/// the colour of `kind`; show it by setting its text and making it visible.
[[nodiscard]] QLabel* noticeLabel(QWidget* parent, const char* name, NoticeKind kind);

} // namespace trimlab::ui
