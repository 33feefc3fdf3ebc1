#include "python/python_progress.h"

#include <string>

namespace trimlab::python {

PythonProgress::PythonProgress(py::object callback) : m_callback(std::move(callback))
{
    if (!m_callback.is_none() && !PyCallable_Check(m_callback.ptr()))
        throw py::type_error("progress must be None or a callable progress(stage, done, total)");
    m_control.stop = m_stop.get_token();
    m_control.progress = [this](const TaskProgress& progress) { report(progress); };
}

PythonProgress::~PythonProgress()
{
    // The callback is a Python object: released with the GIL held (the caller holds it).
    m_callback = py::object();
}

void PythonProgress::report(const TaskProgress& progress)
{
    if (m_error)
        return;
    py::gil_scoped_acquire acquire;
    try {
        if (PyErr_CheckSignals() != 0)
            throw py::error_already_set();
        if (m_callback.is_none())
            return;
        const py::object answer = m_callback(std::string(progress.stage), progress.done, progress.total);
        if (answer.ptr() == Py_False)
            m_stop.request_stop(); // the work ends with OperationCancelled: trimlab.Cancelled

    } catch (py::error_already_set& e) {
        m_error = std::make_unique<py::error_already_set>(std::move(e));
        m_stop.request_stop();
    }
}

void PythonProgress::rethrowCallbackError()
{
    if (m_error) {
        py::error_already_set error = std::move(*m_error);
        m_error.reset();
        throw error;
    }
}

} // namespace trimlab::python
