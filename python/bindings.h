#pragma once
/// \file
/// The module's functions, one group per file: each adds its functions (with their
/// docstrings) to the module. module.cpp calls them in this order.

#include <pybind11/pybind11.h>

namespace trimlab::python {

namespace py = pybind11;

/// load, load_scene, save, info, winding_numbers, demos (bind_mesh.cpp).
void bindMesh(py::module_& module);
/// trim, trim_poses (bind_trim.cpp).
void bindTrim(py::module_& module);
/// load_animation, segment, skin and the Skinning result (bind_animation.cpp).
void bindAnimation(py::module_& module);
/// skeleton (bind_skeleton.cpp).
void bindSkeleton(py::module_& module);
/// render (bind_render.cpp).
void bindRender(py::module_& module);
/// parameters: the parameter tables the keywords read (bind_parameters.cpp).
void bindParameters(py::module_& module);

} // namespace trimlab::python
