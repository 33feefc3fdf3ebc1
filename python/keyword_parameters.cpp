#include "python/keyword_parameters.h"

#include "python/python_errors.h"

#include <cmath>
#include <deque>
#include <mutex>

namespace trimlab::python {

namespace {

std::string givenText(py::handle given)
{
    return py::isinstance<py::str>(given) ? given.cast<std::string>() : std::string(py::repr(given));
}

[[noreturn]] void refuse(const ParameterSpec& spec, py::handle given)
{
    const std::string name = keywordName(spec);
    const std::string range = parameterRangeText(spec);
    const std::string text = givenText(given);
    switch (spec.kind) {
    case ParameterKind::Integer:
        throw ParameterError(name + " must be an integer from " + range + ", got '" + text + "'");
    case ParameterKind::Real:
        throw ParameterError(name + " must be a number from " + range + ", got '" + text + "'");
    case ParameterKind::Boolean:
        throw ParameterError(name + " must be True or False, got '" + text + "'");
    case ParameterKind::Choice:
        break;
    }
    throw ParameterError("unknown " + name + " '" + text + "' (use " + range + ")");
}

// The value `given` spells for `spec`'s kind, the range not checked; refuses other types.
double spelledValue(const ParameterSpec& spec, py::handle given)
{
    switch (spec.kind) {
    case ParameterKind::Boolean:
        if (!py::isinstance<py::bool_>(given))
            refuse(spec, given);
        return given.cast<bool>() ? 1.0 : 0.0;
    case ParameterKind::Integer:
        if (py::isinstance<py::bool_>(given) || !py::isinstance<py::int_>(given))
            refuse(spec, given);
        return double(given.cast<long long>());
    case ParameterKind::Real:
        if (py::isinstance<py::bool_>(given) || !(py::isinstance<py::int_>(given) || py::isinstance<py::float_>(given)))
            refuse(spec, given);
        return given.cast<double>();
    case ParameterKind::Choice:
        break;
    }
    if (!py::isinstance<py::str>(given))
        refuse(spec, given);
    const ChoiceValue* choice = findChoice(spec, given.cast<std::string>());
    if (!choice || !choice->commandLine)
        refuse(spec, given);
    return double(choice->value);
}

} // namespace

const char* keywordName(const ParameterSpec& spec)
{
    static std::mutex mutex;
    static std::deque<std::string> names;
    std::string name(spec.id);
    for (char& c : name)
        if (c == '-')
            c = '_';
    const std::lock_guard lock(mutex);
    for (const std::string& known : names)
        if (known == name)
            return known.c_str();
    return names.emplace_back(std::move(name)).c_str();
}

py::arg_v keywordArgument(const ParameterSpec& spec)
{
    const double value = spec.defaultValue;
    switch (spec.kind) {
    case ParameterKind::Boolean:
        return py::arg_v(keywordName(spec), py::bool_(value != 0.0));
    case ParameterKind::Integer:
        return py::arg_v(keywordName(spec), py::int_(static_cast<long long>(value)));
    case ParameterKind::Real:
        return py::arg_v(keywordName(spec), py::float_(value));
    case ParameterKind::Choice:
        break;
    }
    const ChoiceValue* choice = choiceWithValue(spec, int(value));
    return py::arg_v(keywordName(spec), py::str(std::string(choice ? choice->name : "")));
}

std::string keywordDoc(const ParameterSpec& spec)
{
    return "    " + std::string(keywordName(spec)) + ": " + parameterHelpText(spec) + "\n";
}

double keywordValue(const ParameterSpec& spec, py::handle given)
{
    const double value = spelledValue(spec, given);
    if (!acceptsValue(spec, value))
        refuse(spec, given);
    return value;
}

int keywordInt(const ParameterSpec& spec, py::handle given)
{
    return int(keywordValue(spec, given));
}

bool keywordBool(const ParameterSpec& spec, py::handle given)
{
    return keywordValue(spec, given) != 0.0;
}

} // namespace trimlab::python
