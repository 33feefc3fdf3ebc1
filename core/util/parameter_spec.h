#pragma once
/// \file
/// The one description of a user-facing parameter of an operation: its id, command-line
/// flag, settings key, kind, range, default, unit and one-line help. Every operation
/// (render, bench, skin, skeleton, segment) lists its parameters in a table of these
/// beside its option struct; the command line (app/parameter_options.h), the settings
/// (ui/common/parameter_settings.h) and the forms (ui/common/parameter_form.h) read the
/// table instead of restating ranges, so a range, a default or a help line is written once.
///
/// A spec is a literal type: tables are `inline constexpr` values that a reader scans
/// like a list of options, and `isWellFormed` lets a table check itself at compile time.
/// Values travel as double whatever the kind (integers up to 2^53 are exact); an
/// Integer's value is integral, a Boolean's is 0 or 1, a Choice's is the `value` of one
/// of its ChoiceValues (an enumerator cast to int).

#include <span>
#include <optional>
#include <string>
#include <string_view>

namespace trimlab {

enum class ParameterKind { Integer, Real, Boolean, Choice };

/// One named value of a Choice parameter.
struct ChoiceValue {
    std::string_view name;  ///< stable spelling on the command line and in the settings
    int value;              ///< the enumerator it stands for
    std::string_view label; ///< what forms show
    /// False for a value only the GUI can run (the command line refuses it).
    bool commandLine = true;
};

struct ParameterSpec {
    std::string_view id = {};          ///< unique within its table; the flag where there is one
    std::string_view flag = {};        ///< command-line flag without "--"; empty: not on the command line
    std::string_view settingsKey = {}; ///< QSettings key; empty: not persisted
    ParameterKind kind = ParameterKind::Integer;
    double min = 0.0; ///< Integer, Real (Boolean: 0; Choice: unused)
    double max = 0.0;
    double defaultValue = 0.0;
    std::string_view unit = {}; ///< of the value as stored ("MB"); empty when it has none
    /// One line saying what the parameter does, without range or default (those are
    /// generated: parameterHelpText) and without a final full stop.
    std::string_view help = {};
    std::span<const ChoiceValue> choices = {}; ///< Choice only, in menu order
    /// What `min` stands for when it is special ("all cores", "automatic"); empty if not.
    std::string_view minMeaning = {};
    /// Replaces the default in help texts where the default is no value of the range
    /// ("the last frame"); empty: the formatted defaultValue.
    std::string_view defaultText = {};
    /// The command line needs it (it has no default there; forms still start at defaultValue).
    bool required = false;
    int decimals = 2;  ///< Real: the digits forms show
    double step = 0.0; ///< forms' single step; 0: 1 for Integer, (max − min) / 100 for Real
    /// Boolean only, default off: the command line's --flag takes no value and turns it on
    /// (a switch, like --close-holes); false: --flag on|off.
    bool switchFlag = false;
};

/// True when `value` is a value of `spec`: finite and in [min, max] for Integer and Real,
/// integral for Integer, 0 or 1 for Boolean, one of the choices for Choice.
[[nodiscard]] bool acceptsValue(const ParameterSpec& spec, double value);

/// The value `text` spells, the range not checked: an integer for Integer, a finite
/// number for Real, "on"/"off" (also "true"/"false", "yes"/"no", "1"/"0") for Boolean, a
/// choice's name for Choice. nullopt when it spells none.
[[nodiscard]] std::optional<double> parseParameterValue(const ParameterSpec& spec, std::string_view text);

/// The text of `value`: integral numbers without a fraction, other reals in their
/// shortest exact form, "on"/"off", a choice's name ("?" for an unknown value).
[[nodiscard]] std::string formatParameterValue(const ParameterSpec& spec, double value);

/// The accepted values: "1 to 128", "0 to 0.5", "on or off", "amd, colamd or metis"
/// (command-line choices only).
[[nodiscard]] std::string parameterRangeText(const ParameterSpec& spec);

/// The generated help: help, then the range with its unit and the meaning of min, then
/// the default (with the meaning of min when it is min) or "Required.": "Worker threads
/// (0 to 1024; 0 = all cores). Default: 0 (all cores)." A switch: help and "(a switch;
/// off unless given)."
[[nodiscard]] std::string parameterHelpText(const ParameterSpec& spec);

/// The choice named `name` (any, GUI-only ones included), or nullptr.
[[nodiscard]] const ChoiceValue* findChoice(const ParameterSpec& spec, std::string_view name);
/// The choice whose value is `value`, or nullptr.
[[nodiscard]] const ChoiceValue* choiceWithValue(const ParameterSpec& spec, int value);

/// For core and render code given a value that forms and parsers cannot produce: throws
/// std::invalid_argument("k must be 1 to 128, got 200") unless acceptsValue.
void requireParameterValue(const ParameterSpec& spec, double value);

/// A table row that contradicts itself: min > max, a default outside the range, a
/// Choice without choices or with a default that is none of them, an empty id or help.
[[nodiscard]] constexpr bool isWellFormed(const ParameterSpec& spec)
{
    if (spec.id.empty() || spec.help.empty())
        return false;
    if (spec.kind == ParameterKind::Choice) {
        for (const ChoiceValue& choice : spec.choices)
            if (double(choice.value) == spec.defaultValue)
                return true;
        return false;
    }
    if (spec.switchFlag && (spec.kind != ParameterKind::Boolean || spec.defaultValue != 0.0))
        return false;
    if (spec.kind == ParameterKind::Boolean)
        return spec.min == 0.0 && spec.max == 1.0 && (spec.defaultValue == 0.0 || spec.defaultValue == 1.0);
    const bool integral =
        spec.kind != ParameterKind::Integer ||
        (double(static_cast<long long>(spec.min)) == spec.min && double(static_cast<long long>(spec.max)) == spec.max &&
         double(static_cast<long long>(spec.defaultValue)) == spec.defaultValue);
    return integral && spec.min <= spec.max && spec.defaultValue >= spec.min && spec.defaultValue <= spec.max;
}

/// Every row of `table` is well formed and no two share an id, flag or settings key.
[[nodiscard]] constexpr bool isWellFormedTable(std::span<const ParameterSpec* const> table)
{
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (!isWellFormed(*table[i]))
            return false;
        for (std::size_t j = 0; j < i; ++j) {
            const ParameterSpec& a = *table[i];
            const ParameterSpec& b = *table[j];
            if (a.id == b.id || (!a.flag.empty() && a.flag == b.flag) ||
                (!a.settingsKey.empty() && a.settingsKey == b.settingsKey))
                return false;
        }
    }
    return true;
}

} // namespace trimlab
