#include "core/util/task_control.h"

namespace trimlab {

void TaskControl::report(std::string_view stage, std::size_t done, std::size_t total) const
{
    if (progress)
        progress(TaskProgress{stage, done, total});
}

void TaskControl::throwIfCancelled() const
{
    if (stop.stop_requested())
        throw OperationCancelled();
}

} // namespace trimlab
