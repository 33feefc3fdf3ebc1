#pragma once
/// \file
/// Small builders for the controls of the settings forms (segmentation, skinning,
/// skeleton): each control gets its object name (the UI tests and the settings stores
/// find it by that name) and its tool tip in one call.

#include <QList>
#include <QString>

#include <utility>

class QCheckBox;
class QComboBox;

namespace trimlab::ui {

/// A combo box named `name` holding `items` (text, data) in order, the first current.
[[nodiscard]] QComboBox* namedComboBox(const char* name, const QList<std::pair<QString, int>>& items,
                                       const QString& toolTip);
/// Makes the item whose data is `value` current; keeps the current item when none has it.
void selectItemWithData(QComboBox* box, int value);
/// A check box named `name`.
[[nodiscard]] QCheckBox* namedCheckBox(const QString& text, const char* name, const QString& toolTip);

} // namespace trimlab::ui
