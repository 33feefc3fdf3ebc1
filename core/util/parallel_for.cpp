#include "core/util/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace trimlab {

namespace {

// What the workers share with the waiting caller.
struct LoopState {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> abort{false};
    std::mutex mutex;
    std::condition_variable changed;
    std::size_t finished = 0;
    unsigned runningWorkers = 0;
    std::exception_ptr error;
};

void runWorker(LoopState& state, std::size_t count, const std::function<void(std::size_t)>& body,
               const std::stop_token& stop)
{
    while (!state.abort.load() && !stop.stop_requested()) {
        const std::size_t i = state.next.fetch_add(1);
        if (i >= count)
            break;
        try {
            body(i);
        } catch (...) {
            const std::lock_guard lock(state.mutex);
            if (!state.error)
                state.error = std::current_exception();
            state.abort = true;
        }
        const std::lock_guard lock(state.mutex);
        ++state.finished;
        state.changed.notify_all();
    }
    const std::lock_guard lock(state.mutex);
    --state.runningWorkers;
    state.changed.notify_all();
}

} // namespace

unsigned effectiveThreadCount(unsigned requested, std::size_t count)
{
    unsigned threads = requested == 0 ? std::max(1u, std::thread::hardware_concurrency()) : requested;
    if (count < threads)
        threads = static_cast<unsigned>(std::max<std::size_t>(count, 1));
    return threads;
}

void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                 const TaskControl& control, std::string_view stage)
{
    control.throwIfCancelled();
    control.report(stage, 0, count);
    if (count == 0)
        return;
    LoopState state;
    const unsigned workers = effectiveThreadCount(threads, count);
    state.runningWorkers = workers;
    std::vector<std::jthread> pool;
    pool.reserve(workers);
    for (unsigned w = 0; w < workers; ++w) {
        try {
            pool.emplace_back([&] { runWorker(state, count, body, control.stop); });
        } catch (const std::system_error&) {
            // The system starts no more threads (a memory limit leaves no room for another
            // stack, or the thread limit is reached): the started ones share the items.
            const std::lock_guard lock(state.mutex);
            state.runningWorkers -= workers - w;
            break;
        }
    }
    if (pool.empty()) {
        // Not even one: the calling thread does the work itself.
        state.runningWorkers = 1;
        runWorker(state, count, body, control.stop);
    }
    std::size_t seen = 0;     // finished items the caller has woken up for
    std::size_t reported = 0; // finished items reported to `control`
    std::unique_lock lock(state.mutex);
    while (state.runningWorkers > 0) {
        // Waiting on `seen` (not `reported`) releases the mutex even when nothing is
        // reported any more (after a stop), so the workers can finish.
        state.changed.wait(lock, [&] { return state.finished != seen || state.runningWorkers == 0; });
        seen = state.finished;
        if (seen != reported && !state.abort && !control.stop.stop_requested()) {
            reported = seen;
            lock.unlock();
            control.report(stage, reported, count);
            lock.lock();
        }
    }
    const std::size_t finished = state.finished;
    lock.unlock();
    pool.clear();
    if (state.error)
        std::rethrow_exception(state.error);
    if (finished != reported && !control.stop.stop_requested())
        control.report(stage, finished, count); // the last items may finish between two reports
    control.throwIfCancelled();
}

} // namespace trimlab
