#pragma once
/// \file
/// TrimLab's errors as Python exceptions. Every exception the module raises for a reason
/// a user can fix derives from trimlab.Error; the message is the one the command line
/// prints (without its "error: " prefix):
///
///     Error(Exception)
///     ├── MeshLoadError           a file could not be read: .file, .line, .element, .reason
///     ├── MeshSaveError           a file could not be written (also an OSError)
///     ├── InputError              refused arguments (also a ValueError)
///     │   ├── ParameterError      a value outside its parameter table's range
///     │   ├── NotTrimmableError   a mesh without an inside (open, badly oriented)
///     │   ├── SkeletonInputError  the skeleton refuses the mesh
///     │   ├── SegmentationInputError  too few poses for the feature
///     │   └── SkinningBonesError  the bones cannot be made (a count above #V, ...)
///     ├── Cancelled               the work was stopped (a progress callback asked)
///     └── RenderError             no OpenGL context could be had
///
/// An exception the progress callback raises is not translated: it reaches the caller as
/// raised (python_progress.h).

#include "core/trim/hole_closing.h"

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

namespace trimlab::python {

namespace py = pybind11;

/// Arguments the module refuses before any work: trimlab.InputError.
class InputError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// A keyword outside its parameter table's range: trimlab.ParameterError.
class ParameterError : public InputError {
public:
    using InputError::InputError;
};

/// A mesh or scene whose winding numbers are undefined: trimlab.NotTrimmableError.
class NotTrimmableError : public InputError {
public:
    using InputError::InputError;
};

/// A file the module could not write: trimlab.MeshSaveError.
class MeshSaveError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An OpenGL render that could not start: trimlab.RenderError.
class RenderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A RuntimeWarning with the crossing of `closing` (holeClosingText) when a fan of closed
/// holes crosses the surface; nothing otherwise. Call with the GIL held; a warning the
/// filters turn into an error is raised.
void warnOfCrossingFans(const HoleClosing& closing);

/// Creates the exception classes in `module` and translates TrimLab's C++ exceptions
/// (core's typed errors, the classes above, OperationCancelled; other std::invalid_argument
/// as InputError, other std::runtime_error as Error) into them.
void registerErrors(py::module_& module);

} // namespace trimlab::python
