#pragma once
/// \file
/// The scene and the classification of trim() and render(): one mesh (V, F) or a list of
/// (V, F) pairs (object ids count in list order, as the command line's sources), a static
/// rule by name, a CSG expression over the ids and per-object rules — parsed with the
/// command line's parsers, refused with InputError in its words.

#include "core/catalog/scene_source.h"
#include "core/trim/trim_settings.h"

#include <pybind11/pybind11.h>

namespace trimlab::python {

namespace py = pybind11;

/// `meshes` is V with `triangles` F, or (with `triangles` None) a sequence of (V, F).
/// Objects are named "object 0", "object 1", ...; each gets its validation report.
[[nodiscard]] LoadedScene sceneFromArguments(py::handle meshes, py::handle triangles);

/// `rule`: a rule name (parseStaticRule's spellings); `csg`: None or an expression;
/// `rules`: None, a dict {object id: rule name} or a sequence (one name or None per id).
/// CSG operands and rule ids must be objects of a scene of `objectCount`.
[[nodiscard]] TrimSettings trimSettingsFromArguments(const std::string& rule, py::handle csg, py::handle rules,
                                                     std::size_t objectCount);

/// Throws NotTrimmableError ("no inside to trim: <reason>") unless every object is closed
/// and consistently oriented.
void requireTrimmable(const LoadedScene& loaded);

} // namespace trimlab::python
