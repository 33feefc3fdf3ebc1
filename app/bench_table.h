#pragma once
/// \file
/// The text `trimlab bench` prints: a header (version, OpenGL renderer and version, CPU
/// threads, date, sizes, views, repeat, parameters, what the columns mean) and one row per
/// method, scene and size with median ms per frame and its time source, passes, memory,
/// fragments, lost fragments, overflowed and unresolved pixels, agreement with the CPU
/// reference and the time ratios against F2B and AB_LL of the same run ("n/a" when those
/// did not run).

#include "app/bench_results.h"

#include <QStringList>

namespace trimlab::app {

/// The header lines.
[[nodiscard]] QStringList benchHeaderLines(const BenchHeader& header);
/// The table: a column header line, then one line per cell in report order.
[[nodiscard]] QStringList benchTableLines(const BenchReport& report);
/// One line per cell that failed (disagreement or a render error), naming method, scene
/// and size; empty when everything passed.
[[nodiscard]] QStringList benchFailureLines(const BenchReport& report);

} // namespace trimlab::app
