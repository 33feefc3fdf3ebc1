#include "ui/common/parameter_settings.h"

#include <QSettings>

#include <cmath>

namespace trimlab::ui {

namespace {

QString key(const ParameterSpec& spec)
{
    return QString::fromUtf8(spec.settingsKey.data(), qsizetype(spec.settingsKey.size()));
}

} // namespace

double readParameter(const QSettings& settings, const ParameterSpec& spec)
{
    const QVariant stored = settings.value(key(spec));
    if (!stored.isValid())
        return spec.defaultValue;
    // An integer may have been stored in a real's spelling ("1e+05"); it must still be integral.
    ParameterSpec spelling = spec;
    if (spec.kind == ParameterKind::Integer)
        spelling.kind = ParameterKind::Real;
    const std::optional<double> value = parseParameterValue(spelling, stored.toString().trimmed().toStdString());
    return value && acceptsValue(spec, *value) ? *value : spec.defaultValue;
}

void writeParameter(QSettings& settings, const ParameterSpec& spec, double value)
{
    switch (spec.kind) {
    case ParameterKind::Integer:
        settings.setValue(key(spec), static_cast<qlonglong>(value));
        return;
    case ParameterKind::Real:
        settings.setValue(key(spec), value);
        return;
    case ParameterKind::Boolean:
        settings.setValue(key(spec), value != 0.0);
        return;
    case ParameterKind::Choice:
        settings.setValue(key(spec), QString::fromStdString(formatParameterValue(spec, value)));
        return;
    }
}

double readBoundedNumber(const QSettings& settings, const QString& key, double lo, double hi, double fallback)
{
    bool ok = false;
    const double value = settings.value(key).toDouble(&ok);
    return ok && std::isfinite(value) && value >= lo && value <= hi ? value : fallback;
}

int readBoundedInteger(const QSettings& settings, const QString& key, int lo, int hi, int fallback)
{
    const double value = readBoundedNumber(settings, key, lo, hi, fallback);
    return value == std::round(value) ? int(value) : fallback;
}

} // namespace trimlab::ui
