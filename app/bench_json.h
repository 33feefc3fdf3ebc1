#pragma once
/// \file
/// `trimlab bench --json FILE`: the same data as the table, as JSON.
///
/// { "header": { "version", "openGl", "cpuThreads", "date", "sizes": ["1024x768"], "views",
///               "repeat", "k", "sharedCounters", "locks": "auto" | "spin" | "both",
///               "methods": ["kplus-array", ...],
///               "scenes": [...] },
///   "skipped": [ { "scene", "reason" } ],
///   "results": [ { "scene", "size", "width", "height", "method", "methodName", "bounded",
///                  "status": "ok" | "disagrees" | "out-of-memory" | "not-applicable" |
///                  "failed", "error",
///                  "msPerFrame", "timeSource": "GPU" | "wall", "gpuMsMedian" (null when
///                  not every frame had one), "wallMsMedian", "frames", "views",
///                  "geometryPasses", "fullscreenPasses", "megabytes", "interlock",
///                  "lock": "interlock" | "spin-lock" | "none",
///                  "fragmentsInSpan", "fragmentsStored", "fragmentsLost", "overflowPixels",
///                  "unresolvedPixels", "spinGiveUps", "agreementPercent",
///                  "worstViewAgreementPercent", "comparedPixels", "excludedPercent",
///                  "overflowedPixelsNotCompared", "violation", "ratioToF2B", "ratioToABLL",
///                  "ratioToInterlock" (a spin-lock cell / the same method's interlock cell)
///                  (null: n/a) } ] }
/// Cells that did not render carry only the identity fields, status and error.

#include "app/bench_results.h"

#include <QByteArray>
#include <QString>

namespace trimlab::app {

/// The report as indented JSON.
[[nodiscard]] QByteArray benchJson(const BenchReport& report);
/// Writes benchJson(report) to `path` atomically (a temporary file renamed over it);
/// throws std::runtime_error naming the file on failure.
void writeBenchJson(const BenchReport& report, const QString& path);

} // namespace trimlab::app
