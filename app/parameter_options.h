#pragma once
/// \file
/// The command-line binder of the parameter tables (core/util/parameter_spec.h): the
/// QCommandLineOption of a row (its help generated from the row's range, default and
/// unit, so no help string states a range), and the parse of a given flag with the
/// one-line error every verb prints for a bad value — "--k must be an integer from 1 to
/// 128, got '0'", "unknown --ordering 'rcm' (use amd, colamd or metis)". A flag not
/// given leaves its value as it was: the option struct's default, which is the row's.

#include "core/util/parameter_spec.h"

#include <QCommandLineOption>
#include <QString>

#include <optional>
#include <span>
#include <type_traits>

class QCommandLineParser;

namespace trimlab::app {

/// The option of a row with a flag: --flag VALUE, help parameterHelpText, value name N
/// (integers), X (reals), on|off or the choices' names joined by '|'.
[[nodiscard]] QCommandLineOption commandLineOption(const ParameterSpec& spec);

/// Adds commandLineOption of every row of `table` that has a flag.
void addParameterOptions(QCommandLineParser& parser, std::span<const ParameterSpec* const> table);

/// When --flag was given: its value, which must be one of the row's (acceptsValue; a
/// choice the command line cannot run counts as unknown), into `value`; else the
/// one-line error. Not given: nullopt and `value` unchanged.
[[nodiscard]] std::optional<QString> parseParameter(const QCommandLineParser& parser, const ParameterSpec& spec,
                                                    double& value);

/// The same into a field of an option struct: an integer, a real, a bool or an enum
/// (a Choice row's values are its enumerators).
template <typename T>
[[nodiscard]] std::optional<QString> parseParameter(const QCommandLineParser& parser, const ParameterSpec& spec,
                                                    T& field)
{
    double value = 0.0;
    if constexpr (std::is_enum_v<T>)
        value = double(static_cast<std::underlying_type_t<T>>(field));
    else
        value = double(field);
    if (std::optional<QString> error = parseParameter(parser, spec, value))
        return error;
    if constexpr (std::is_same_v<T, bool>)
        field = value != 0.0;
    else if constexpr (std::is_enum_v<T>)
        field = static_cast<T>(static_cast<std::underlying_type_t<T>>(value));
    else
        field = static_cast<T>(value);
    return std::nullopt;
}

} // namespace trimlab::app
