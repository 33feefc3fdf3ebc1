#include "python/python_errors.h"

#include "core/animation/segmentation_run.h"
#include "core/mesh/mesh_load_error.h"
#include "core/skeleton/skeleton_input.h"
#include "core/skinning/skinning_pipeline.h"
#include "core/util/printable_text.h"
#include "core/util/task_control.h"

namespace trimlab::python {

namespace {

// The classes live as long as the interpreter (the module is never unloaded).
struct ErrorClasses {
    PyObject* error = nullptr;
    PyObject* meshLoad = nullptr;
    PyObject* meshSave = nullptr;
    PyObject* input = nullptr;
    PyObject* parameter = nullptr;
    PyObject* notTrimmable = nullptr;
    PyObject* skeletonInput = nullptr;
    PyObject* segmentationInput = nullptr;
    PyObject* skinningBones = nullptr;
    PyObject* cancelled = nullptr;
    PyObject* render = nullptr;
};

ErrorClasses& classes()
{
    static ErrorClasses instance;
    return instance;
}

PyObject* makeClass(py::module_& module, const char* name, py::tuple bases, const char* doc)
{
    const std::string qualified = "trimlab." + std::string(name);
    PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
    if (!type)
        throw py::error_already_set();
    module.add_object(name, py::handle(type));
    return type;
}

// Messages quote files: escaped (printable_text.h), they are valid UTF-8 for Python's str
// and print no control sequence.
void raise(PyObject* type, const std::exception& e)
{
    PyErr_SetString(type, printableText(e.what()).c_str());
}

// A MeshLoadError carries where the file went wrong as attributes.
void raiseMeshLoad(const MeshLoadError& e)
{
    py::object error = py::reinterpret_borrow<py::object>(classes().meshLoad)(printableText(e.what()));
    error.attr("file") = printableText(e.file());
    error.attr("line") = e.line() ? py::int_(*e.line()) : py::object(py::none());
    error.attr("element") = printableText(e.element());
    error.attr("reason") = printableText(e.reason());
    PyErr_SetObject(classes().meshLoad, error.ptr());
}

void translate(std::exception_ptr pointer)
{
    const ErrorClasses& c = classes();
    try {
        std::rethrow_exception(pointer);
    } catch (const MeshLoadError& e) {
        raiseMeshLoad(e);
    } catch (const ParameterError& e) {
        raise(c.parameter, e);
    } catch (const NotTrimmableError& e) {
        raise(c.notTrimmable, e);
    } catch (const InputError& e) {
        raise(c.input, e);
    } catch (const SkeletonInputError& e) {
        raise(c.skeletonInput, e);
    } catch (const SegmentationInputError& e) {
        raise(c.segmentationInput, e);
    } catch (const SkinningBonesError& e) {
        raise(c.skinningBones, e);
    } catch (const OperationCancelled& e) {
        raise(c.cancelled, e);
    } catch (const MeshSaveError& e) {
        raise(c.meshSave, e);
    } catch (const RenderError& e) {
        raise(c.render, e);
    } catch (const std::invalid_argument& e) {
        raise(c.input, e);
    } catch (const std::runtime_error& e) {
        raise(c.error, e);
    }
}

} // namespace

void warnOfCrossingFans(const HoleClosing& closing)
{
    if (closing.crossing.empty())
        return;
    const std::string text = "closed " + holeClosingText(closing);
    if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 1) != 0)
        throw py::error_already_set();
}

void registerErrors(py::module_& module)
{
    ErrorClasses& c = classes();
    const py::handle exception(PyExc_Exception);
    c.error = makeClass(module, "Error", py::make_tuple(exception), "Base of every error TrimLab raises.");
    const py::handle error(c.error);
    c.meshLoad = makeClass(module, "MeshLoadError", py::make_tuple(error),
                           "A mesh or animation file could not be read. Attributes: file, line (or None), "
                           "element (e.g. 'face 17', or ''), reason.");
    c.meshSave = makeClass(module, "MeshSaveError", py::make_tuple(error, py::handle(PyExc_OSError)),
                           "A file could not be written.");
    c.input = makeClass(module, "InputError", py::make_tuple(error, py::handle(PyExc_ValueError)),
                        "Refused arguments: array shapes, indices, rule names, CSG expressions.");
    const py::handle input(c.input);
    c.parameter = makeClass(module, "ParameterError", py::make_tuple(input),
                            "A keyword argument outside the range of its parameter table.");
    c.notTrimmable = makeClass(module, "NotTrimmableError", py::make_tuple(input),
                               "The winding numbers are undefined: the mesh is open or badly oriented.");
    c.skeletonInput =
        makeClass(module, "SkeletonInputError", py::make_tuple(input), "The skeleton extraction refuses the mesh.");
    c.segmentationInput = makeClass(module, "SegmentationInputError", py::make_tuple(input),
                                    "The segmentation has too few poses to partition.");
    c.skinningBones = makeClass(module, "SkinningBonesError", py::make_tuple(input),
                                "The skinning fit cannot make its bones (e.g. more bones than vertices).");
    c.cancelled = makeClass(module, "Cancelled", py::make_tuple(error), "The work was stopped before it finished.");
    c.render = makeClass(module, "RenderError", py::make_tuple(error), "No OpenGL context could be had.");
    py::register_exception_translator(translate);
}

} // namespace trimlab::python
