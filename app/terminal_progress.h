#pragma once
/// \file
/// What the long batch verbs (skin, skeleton) share about time: progress lines for a
/// person watching a terminal, and the lap times their summaries print.

#include "core/util/task_control.h"

class QElapsedTimer;

namespace trimlab::app {

/// Progress on stderr, one line per stage rewritten in place — only when stderr is a
/// terminal (scripts read a single error line there).
[[nodiscard]] TaskControl terminalProgress();

/// Milliseconds since `timer` last started, and restarts it (one lap).
double lapMilliseconds(QElapsedTimer& timer);

} // namespace trimlab::app
