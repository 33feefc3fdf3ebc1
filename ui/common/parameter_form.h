#pragma once
/// \file
/// The form binder of the parameter tables (core/util/parameter_spec.h): a spin box, combo
/// box or check box takes its range, step, decimals, the text of a special minimum
/// ("all cores"), its unit and its tooltip from the row, and combo boxes their items
/// (the choices' labels, each with its value as item data). A form built this way cannot
/// hold a value outside the row's range, and its tooltip says what the command line's
/// help says. Each control remembers its row's id in the property "parameterId".

#include "core/util/parameter_spec.h"

#include <QString>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class QWidget;

namespace trimlab::ui {

/// The tooltip of a row: its help text with range and default (parameterHelpText).
[[nodiscard]] QString parameterToolTip(const ParameterSpec& spec);

/// Range, single step, special minimum, " unit" suffix and tooltip of an Integer row.
void applyParameter(QSpinBox* box, const ParameterSpec& spec);
/// The same for a Real row, shown `scale` times its value (100: a fraction as percent;
/// the caller then sets the suffix, and the tooltip is the row's help alone).
void applyParameter(QDoubleSpinBox* box, const ParameterSpec& spec, double scale = 1.0);
/// The choices of a Choice row as items (label, value), GUI-only ones included, and its tooltip.
void applyParameter(QComboBox* box, const ParameterSpec& spec);
/// The tooltip of a Boolean row.
void applyParameter(QCheckBox* box, const ParameterSpec& spec);

/// A new control named `objectName` with applyParameter done, at the row's default.
[[nodiscard]] QSpinBox* parameterSpinBox(const ParameterSpec& spec, const char* objectName, QWidget* parent = nullptr);
[[nodiscard]] QDoubleSpinBox* parameterDoubleSpinBox(const ParameterSpec& spec, const char* objectName,
                                                     QWidget* parent = nullptr);
[[nodiscard]] QComboBox* parameterComboBox(const ParameterSpec& spec, const char* objectName,
                                           QWidget* parent = nullptr);
[[nodiscard]] QCheckBox* parameterCheckBox(const ParameterSpec& spec, const QString& text, const char* objectName,
                                           QWidget* parent = nullptr);

} // namespace trimlab::ui
