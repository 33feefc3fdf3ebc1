#include "core/util/parameter_spec.h"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace trimlab {

namespace {

std::string numberText(double value)
{
    if (std::isfinite(value) && value == std::round(value) && std::abs(value) < 1e15)
        return std::to_string(static_cast<long long>(value));
    char buffer[64];
    const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::optional<long long> parseInteger(std::string_view text)
{
    long long value = 0;
    const std::from_chars_result result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size())
        return std::nullopt;
    return value;
}

std::optional<double> parseReal(std::string_view text)
{
    // from_chars refuses a leading '+', which people type; nothing else is skipped.
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    double value = 0.0;
    const std::from_chars_result result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::optional<double> parseBoolean(std::string_view text)
{
    for (const std::string_view yes : {"on", "true", "yes", "1"})
        if (text == yes)
            return 1.0;
    for (const std::string_view no : {"off", "false", "no", "0"})
        if (text == no)
            return 0.0;
    return std::nullopt;
}

// "a", "a or b", "a, b or c".
std::string alternatives(std::span<const ChoiceValue> choices)
{
    std::string text;
    std::size_t count = 0;
    for (const ChoiceValue& choice : choices)
        count += choice.commandLine ? 1 : 0;
    std::size_t written = 0;
    for (const ChoiceValue& choice : choices) {
        if (!choice.commandLine)
            continue;
        if (written > 0)
            text += written + 1 == count ? " or " : ", ";
        text += choice.name;
        ++written;
    }
    return text;
}

std::string withUnit(std::string text, std::string_view unit)
{
    if (!unit.empty())
        (text += ' ') += unit;
    return text;
}

} // namespace

bool acceptsValue(const ParameterSpec& spec, double value)
{
    if (!std::isfinite(value))
        return false;
    switch (spec.kind) {
    case ParameterKind::Choice:
        return value == std::round(value) && std::abs(value) < 1e9 && choiceWithValue(spec, int(value)) != nullptr;
    case ParameterKind::Boolean:
        return value == 0.0 || value == 1.0;
    case ParameterKind::Integer:
        if (value != std::round(value))
            return false;
        break;
    case ParameterKind::Real:
        break;
    }
    return value >= spec.min && value <= spec.max;
}

std::optional<double> parseParameterValue(const ParameterSpec& spec, std::string_view text)
{
    switch (spec.kind) {
    case ParameterKind::Integer:
        if (const std::optional<long long> value = parseInteger(text))
            return double(*value);
        return std::nullopt;
    case ParameterKind::Real:
        return parseReal(text);
    case ParameterKind::Boolean:
        return parseBoolean(text);
    case ParameterKind::Choice:
        if (const ChoiceValue* choice = findChoice(spec, text))
            return double(choice->value);
        return std::nullopt;
    }
    return std::nullopt;
}

std::string formatParameterValue(const ParameterSpec& spec, double value)
{
    switch (spec.kind) {
    case ParameterKind::Boolean:
        return value != 0.0 ? "on" : "off";
    case ParameterKind::Choice: {
        const ChoiceValue* choice = std::isfinite(value) ? choiceWithValue(spec, int(value)) : nullptr;
        return choice ? std::string(choice->name) : std::string("?");
    }
    case ParameterKind::Integer:
    case ParameterKind::Real:
        break;
    }
    return numberText(value);
}

std::string parameterRangeText(const ParameterSpec& spec)
{
    switch (spec.kind) {
    case ParameterKind::Boolean:
        return "on or off";
    case ParameterKind::Choice:
        return alternatives(spec.choices);
    case ParameterKind::Integer:
    case ParameterKind::Real:
        break;
    }
    return numberText(spec.min) + " to " + numberText(spec.max);
}

std::string parameterHelpText(const ParameterSpec& spec)
{
    std::string text(spec.help);
    if (spec.switchFlag)
        return text + " (a switch; off unless given).";
    std::string range = spec.kind == ParameterKind::Integer || spec.kind == ParameterKind::Real
                            ? withUnit(parameterRangeText(spec), spec.unit)
                            : parameterRangeText(spec);
    if (!spec.minMeaning.empty())
        range += "; " + numberText(spec.min) + " = " + std::string(spec.minMeaning);
    text += " (" + range + ").";
    if (spec.required)
        return text + " Required.";
    if (!spec.defaultText.empty())
        return text + " Default: " + std::string(spec.defaultText) + ".";
    const bool numeric = spec.kind == ParameterKind::Integer || spec.kind == ParameterKind::Real;
    std::string value = formatParameterValue(spec, spec.defaultValue);
    if (numeric && !spec.minMeaning.empty() && spec.defaultValue == spec.min)
        value += " (" + std::string(spec.minMeaning) + ")";
    else if (numeric)
        value = withUnit(value, spec.unit);
    return text + " Default: " + value + ".";
}

const ChoiceValue* findChoice(const ParameterSpec& spec, std::string_view name)
{
    for (const ChoiceValue& choice : spec.choices)
        if (choice.name == name)
            return &choice;
    return nullptr;
}

const ChoiceValue* choiceWithValue(const ParameterSpec& spec, int value)
{
    for (const ChoiceValue& choice : spec.choices)
        if (choice.value == value)
            return &choice;
    return nullptr;
}

void requireParameterValue(const ParameterSpec& spec, double value)
{
    if (!acceptsValue(spec, value))
        throw std::invalid_argument(std::string(spec.id) + " must be " + parameterRangeText(spec) + ", got " +
                                    numberText(value));
}

} // namespace trimlab
