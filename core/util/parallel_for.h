#pragma once
/// \file
/// A small thread pool loop for independent items (one pose each): the results are
/// whatever `body` writes for its index, so they do not depend on the thread count.

#include "core/util/task_control.h"

#include <cstddef>
#include <functional>
#include <string_view>

namespace trimlab {

/// Calls `body(i)` once for every i in [0, count) on up to `threads` threads (0 = the
/// hardware concurrency; never more threads than items). Items are handed out in
/// increasing order. The calling thread only waits, reports progress through `control`
/// (stage `stage`, after every finished item) and checks for cancellation. When the
/// system refuses to start a thread (under a memory or thread limit) the threads started
/// share the items; when it starts none, the calling thread runs them all.
/// - `body` must be safe to run concurrently for different indices.
/// - The first exception thrown by `body` stops the handing out of further items and is
///   rethrown here after every running item has finished.
/// - When `control.stop` is requested, no further items start and OperationCancelled is
///   thrown after the running ones have finished.
void parallelFor(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                 const TaskControl& control = {}, std::string_view stage = "work");

/// The number of worker threads parallelFor uses for `requested` (0 = hardware) and
/// `count` items: at least 1, at most `count`.
[[nodiscard]] unsigned effectiveThreadCount(unsigned requested, std::size_t count);

} // namespace trimlab
