#pragma once
/// \file
/// Keyword arguments from a parameter table (core/util/parameter_spec.h), so that a
/// Python default, range, choice name and help line is the table's and written nowhere
/// else. A row's keyword is its id with '-' as '_' ("heat-constant" → heat_constant).
/// Integers take Python ints, reals any number, booleans bools, choices the names the
/// command line takes ("rigid", "lbs"). A refused value raises trimlab.ParameterError in
/// the command line's words with the keyword for the flag: "bones must be an integer
/// from 1 to 65535, got 0".

#include "core/util/parameter_spec.h"

#include <pybind11/pybind11.h>

#include <string>

namespace trimlab::python {

namespace py = pybind11;

/// The keyword of `spec` (its id, '_' for '-'). The string lives as long as the process.
[[nodiscard]] const char* keywordName(const ParameterSpec& spec);
/// py::arg for `spec` with the table's default as a Python value.
[[nodiscard]] py::arg_v keywordArgument(const ParameterSpec& spec);
/// One docstring line: "name: help (range). Default: value."
[[nodiscard]] std::string keywordDoc(const ParameterSpec& spec);
/// The value given for `spec` as the table's double (a choice's value), checked.
[[nodiscard]] double keywordValue(const ParameterSpec& spec, py::handle given);

/// keywordValue as an int / a bool.
[[nodiscard]] int keywordInt(const ParameterSpec& spec, py::handle given);
[[nodiscard]] bool keywordBool(const ParameterSpec& spec, py::handle given);

} // namespace trimlab::python
