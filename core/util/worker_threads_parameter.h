#pragma once
/// \file
/// The worker threads every parallel operation lets users choose: one limit and one row
/// shape for all their parameter tables (core/util/parameter_spec.h), 0 meaning every core.
/// Results never depend on the count; it only bounds the cores used.

#include "core/util/parameter_spec.h"

#include <string_view>

namespace trimlab {

/// The most worker threads an option may ask for.
inline constexpr int kMaxWorkerThreads = 1024;

/// The "threads" row of an operation's table, with its settings key (empty: not
/// persisted) and help line.
[[nodiscard]] constexpr ParameterSpec workerThreadsParameter(std::string_view settingsKey, std::string_view help)
{
    return {
        .id = "threads",
        .flag = "threads",
        .settingsKey = settingsKey,
        .kind = ParameterKind::Integer,
        .min = 0,
        .max = kMaxWorkerThreads,
        .defaultValue = 0,
        .help = help,
        .minMeaning = "all cores",
    };
}

} // namespace trimlab
