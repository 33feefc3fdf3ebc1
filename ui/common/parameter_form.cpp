#include "ui/common/parameter_form.h"

#include "ui/common/form_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>

#include <algorithm>
#include <cmath>

namespace trimlab::ui {

namespace {

QString text(std::string_view view)
{
    return QString::fromUtf8(view.data(), qsizetype(view.size()));
}

void markParameter(QWidget* widget, const ParameterSpec& spec)
{
    widget->setProperty("parameterId", text(spec.id));
}

} // namespace

QString parameterToolTip(const ParameterSpec& spec)
{
    return QString::fromStdString(parameterHelpText(spec));
}

void applyParameter(QSpinBox* box, const ParameterSpec& spec)
{
    box->setRange(int(spec.min), int(spec.max));
    box->setSingleStep(spec.step > 0.0 ? std::max(1, int(spec.step)) : 1);
    box->setSpecialValueText(text(spec.minMeaning));
    box->setSuffix(spec.unit.empty() ? QString() : QLatin1Char(' ') + text(spec.unit));
    box->setToolTip(parameterToolTip(spec));
    markParameter(box, spec);
}

void applyParameter(QDoubleSpinBox* box, const ParameterSpec& spec, double scale)
{
    // The decimals first: setRange rounds the bounds to them.
    const int shift = int(std::lround(std::log10(scale)));
    box->setDecimals(std::max(0, spec.decimals - shift));
    box->setRange(spec.min * scale, spec.max * scale);
    box->setSingleStep((spec.step > 0.0 ? spec.step : (spec.max - spec.min) / 100.0) * scale);
    box->setSpecialValueText(text(spec.minMeaning));
    if (scale == 1.0) {
        box->setSuffix(spec.unit.empty() ? QString() : QLatin1Char(' ') + text(spec.unit));
        box->setToolTip(parameterToolTip(spec));
    } else {
        box->setToolTip(text(spec.help));
    }
    markParameter(box, spec);
}

void applyParameter(QComboBox* box, const ParameterSpec& spec)
{
    if (box->count() == 0)
        for (const ChoiceValue& choice : spec.choices)
            box->addItem(text(choice.label), choice.value);
    box->setToolTip(parameterToolTip(spec));
    markParameter(box, spec);
}

void applyParameter(QCheckBox* box, const ParameterSpec& spec)
{
    box->setToolTip(parameterToolTip(spec));
    markParameter(box, spec);
}

QSpinBox* parameterSpinBox(const ParameterSpec& spec, const char* objectName, QWidget* parent)
{
    auto* box = new QSpinBox(parent);
    box->setObjectName(QLatin1String(objectName));
    applyParameter(box, spec);
    box->setValue(int(spec.defaultValue));
    return box;
}

QDoubleSpinBox* parameterDoubleSpinBox(const ParameterSpec& spec, const char* objectName, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(QLatin1String(objectName));
    applyParameter(box, spec);
    box->setValue(spec.defaultValue);
    return box;
}

QComboBox* parameterComboBox(const ParameterSpec& spec, const char* objectName, QWidget* parent)
{
    auto* box = new QComboBox(parent);
    box->setObjectName(QLatin1String(objectName));
    applyParameter(box, spec);
    selectItemWithData(box, int(spec.defaultValue));
    return box;
}

QCheckBox* parameterCheckBox(const ParameterSpec& spec, const QString& label, const char* objectName, QWidget* parent)
{
    auto* box = new QCheckBox(label, parent);
    box->setObjectName(QLatin1String(objectName));
    applyParameter(box, spec);
    box->setChecked(spec.defaultValue != 0.0);
    return box;
}

} // namespace trimlab::ui
