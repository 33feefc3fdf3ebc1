#pragma once
/// \file
/// Long work from Python: the GIL released while core code runs, progress through an
/// optional callback `progress(stage: str, done: int, total: int)`, and cancellation by
/// an exception raised from it. The callback runs with the GIL held, on the calling
/// thread (TaskControl's contract). An exception it raises (KeyboardInterrupt from
/// Ctrl+C included: signals are checked at every report) requests the stop; the work ends
/// at its next poll with OperationCancelled, and the callback's exception — not
/// trimlab.Cancelled — reaches the caller. A callback that returns False stops the work
/// the same way, and the caller gets trimlab.Cancelled.

#include "core/util/task_control.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <stop_token>
#include <utility>

namespace trimlab::python {

namespace py = pybind11;

class PythonProgress {
public:
    /// `callback` is None or a callable of (stage, done, total).
    explicit PythonProgress(py::object callback);
    ~PythonProgress();
    PythonProgress(const PythonProgress&) = delete;
    PythonProgress& operator=(const PythonProgress&) = delete;

    /// The control to hand to core code (valid while this object lives).
    [[nodiscard]] const TaskControl& control() const { return m_control; }
    /// Rethrows what the callback raised, if it raised; call with the GIL held.
    void rethrowCallbackError();

private:
    void report(const TaskProgress& progress);

    py::object m_callback;
    std::stop_source m_stop;
    std::unique_ptr<py::error_already_set> m_error;
    TaskControl m_control;
};

/// Runs `work(control)` with the GIL released and returns its result. The callback's
/// exception, when it raised one, replaces whatever the work ended with — also when the
/// work finished before it polled the stop again.
template <class Work>
auto runWithProgress(const py::object& callback, Work&& work)
{
    PythonProgress progress(callback);
    std::optional<decltype(work(progress.control()))> result;
    try {
        py::gil_scoped_release release;
        result.emplace(std::forward<Work>(work)(progress.control()));
    } catch (...) {
        progress.rethrowCallbackError();
        throw;
    }
    progress.rethrowCallbackError();
    return std::move(*result);
}

} // namespace trimlab::python
