#pragma once
/// \file
/// An animation given as arrays — poses (k, n, 3) and triangles F (m, 3) — as the core's
/// MeshAnimation, for every function that takes one (segment, skin, trim_poses). Each
/// pose is named "pose K"; the rest pose is the keyword's (its parameter table's range)
/// and must exist. Refusals are InputError (python_errors.h) in the loaders' words.

#include "core/animation/mesh_animation.h"

#include <pybind11/pybind11.h>

namespace trimlab::python {

namespace py = pybind11;

/// The animation of `poses` over `triangles` with rest pose `restPose` (None: the
/// parameter's default). Throws InputError for an empty or malformed animation and
/// ParameterError for a rest pose it does not have.
[[nodiscard]] MeshAnimation animationFromArrays(py::handle poses, py::handle triangles, py::handle restPose);

} // namespace trimlab::python
