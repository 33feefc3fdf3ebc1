#include "python/bindings.h"
#include "python/python_errors.h"

PYBIND11_MODULE(_trimlab, module)
{
    module.doc() = "TrimLab's core operations over NumPy arrays (see the trimlab package).";
    trimlab::python::registerErrors(module);
    trimlab::python::bindMesh(module);
    trimlab::python::bindTrim(module);
    trimlab::python::bindAnimation(module);
    trimlab::python::bindSkeleton(module);
    trimlab::python::bindRender(module);
    trimlab::python::bindParameters(module);
}
