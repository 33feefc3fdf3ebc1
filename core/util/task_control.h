#pragma once
/// \file
/// Progress reporting and cancellation for long animation work (loading a sequence,
/// computing features and pose partitions), so that a panel can show a progress bar and a
/// Cancel button while the work runs on a worker thread.

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <string_view>

namespace trimlab {

/// Thrown by long operations when their TaskControl's stop token was triggered. The
/// operation leaves every object it was called on as it was before the call.
class OperationCancelled : public std::runtime_error {
public:
    OperationCancelled() : std::runtime_error("the operation was cancelled") {}
};

/// One progress report: `done` of `total` items of the stage `stage` ("load",
/// "features", "partitions", ...) are finished.
struct TaskProgress {
    std::string_view stage;
    std::size_t done = 0;
    std::size_t total = 0;
};

/// What a caller hands to a long operation. Both parts are optional.
/// - `progress` is called on the thread that called the operation (never from a worker
///   thread), at least once per stage and after every finished item, in order.
/// - `stop` is polled between items; once stop is requested the operation throws
///   OperationCancelled as soon as the running items have finished.
struct TaskControl {
    std::function<void(const TaskProgress&)> progress;
    std::stop_token stop;

    /// Calls `progress` when set.
    void report(std::string_view stage, std::size_t done, std::size_t total) const;
    /// Throws OperationCancelled when stop was requested.
    void throwIfCancelled() const;
};

} // namespace trimlab
