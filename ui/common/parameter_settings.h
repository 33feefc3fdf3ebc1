#pragma once
/// \file
/// The settings binder of the parameter tables (core/util/parameter_spec.h): one row read
/// from or written to a QSettings at the row's settingsKey. A stored value that is
/// missing, unparsable or not one of the row's values (out of range, not integral, an
/// unknown choice name) reads as the row's default, so a damaged or hand-edited settings
/// file never reaches the code or a form with a value they cannot show. Numbers are
/// stored as numbers, booleans as booleans and choices by their names, as the settings
/// stores always wrote them.

#include "core/util/parameter_spec.h"

#include <QString>

#include <type_traits>

class QSettings;

namespace trimlab::ui {

/// The stored value of `spec`, or its default (see above).
[[nodiscard]] double readParameter(const QSettings& settings, const ParameterSpec& spec);
/// Stores `value` at the row's key (a choice as its name).
void writeParameter(QSettings& settings, const ParameterSpec& spec, double value);

/// readParameter as the type of an option struct's field: an integer, a real, a bool or
/// an enum (a Choice row's values are its enumerators).
template <typename T>
[[nodiscard]] T readParameterAs(const QSettings& settings, const ParameterSpec& spec)
{
    const double value = readParameter(settings, spec);
    if constexpr (std::is_same_v<T, bool>)
        return value != 0.0;
    else if constexpr (std::is_enum_v<T>)
        return static_cast<T>(static_cast<std::underlying_type_t<T>>(value));
    else
        return static_cast<T>(value);
}

/// writeParameter from a field of an option struct.
template <typename T>
void writeParameterFrom(QSettings& settings, const ParameterSpec& spec, T field)
{
    if constexpr (std::is_enum_v<T>)
        writeParameter(settings, spec, double(static_cast<std::underlying_type_t<T>>(field)));
    else
        writeParameter(settings, spec, double(field));
}

/// For stores without a table: the stored number at `key` when finite and in [lo, hi],
/// else `fallback`.
[[nodiscard]] double readBoundedNumber(const QSettings& settings, const QString& key, double lo, double hi,
                                       double fallback);
/// The same for an integer: a stored fraction also reads as `fallback`.
[[nodiscard]] int readBoundedInteger(const QSettings& settings, const QString& key, int lo, int hi, int fallback);

} // namespace trimlab::ui
