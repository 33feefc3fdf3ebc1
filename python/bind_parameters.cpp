#include "python/bindings.h"
#include "python/keyword_parameters.h"
#include "python/python_errors.h"

#include "core/animation/segmentation_parameters.h"
#include "core/skeleton/skeleton_parameters.h"
#include "core/skinning/skinning_parameters.h"

namespace trimlab::python {

namespace {

const char* kindName(ParameterKind kind)
{
    switch (kind) {
    case ParameterKind::Integer:
        return "int";
    case ParameterKind::Real:
        return "float";
    case ParameterKind::Boolean:
        return "bool";
    case ParameterKind::Choice:
        break;
    }
    return "choice";
}

py::dict rowDict(const ParameterSpec& spec)
{
    py::dict d;
    d["name"] = keywordName(spec);
    d["kind"] = kindName(spec.kind);
    d["min"] = spec.min;
    d["max"] = spec.max;
    d["default"] = keywordArgument(spec).value;
    d["range"] = parameterRangeText(spec);
    d["help"] = parameterHelpText(spec);
    py::list choices;
    for (const ChoiceValue& choice : spec.choices)
        if (choice.commandLine)
            choices.append(py::make_tuple(std::string(choice.name), std::string(choice.label)));
    d["choices"] = choices;
    return d;
}

template <std::size_t N>
py::list tableList(const std::array<const ParameterSpec*, N>& table)
{
    py::list rows;
    for (const ParameterSpec* spec : table)
        rows.append(rowDict(*spec));
    return rows;
}

py::list parameters(const std::string& operation)
{
    if (operation == "skin")
        return tableList(skinning_parameters::kTable);
    if (operation == "skeleton")
        return tableList(skeleton_parameters::kTable);
    if (operation == "segment")
        return tableList(segmentation_parameters::kTable);
    throw InputError("unknown operation '" + operation + "' (use skin, skeleton or segment)");
}

} // namespace

void bindParameters(py::module_& m)
{
    m.def("parameters", &parameters, py::arg("operation"),
          "parameters(operation) -> list of dict\n\nThe parameter table of 'skin', 'skeleton' or 'segment', one "
          "dict per row: name (the keyword), kind (int, float, bool, choice), min, max, default, range, help and "
          "choices ((name, label) pairs). The keyword arguments and the Blender add-on's fields read it, so a "
          "range or default is written once, in C++.");
}

} // namespace trimlab::python
