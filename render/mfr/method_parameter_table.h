#pragma once
/// \file
/// The parameters of the multi-fragment methods that users choose (MethodParameters):
/// k, S and the GPU memory budget — for `trimlab render`, `trimlab bench` and the Render
/// panel alike. Limits and defaults are MethodParameters' own; the rows add flag,
/// settings key, unit and help. validateMethodParameters is the one check of a
/// MethodParameters value: the command line refuses, the settings fall back and the
/// forms cannot leave these ranges, so a value it refuses is a programmer's error.

#include "core/util/parameter_spec.h"
#include "render/mfr/fragment_method.h"

#include <array>

namespace trimlab::render::method_parameters {

inline constexpr ParameterSpec kK{
    .id = "k",
    .flag = "k",
    .settingsKey = "render/k",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = MethodParameters::kMaxK,
    .defaultValue = MethodParameters{}.k,
    .help = "Fragments kept per pixel by the capacity-bounded methods (k+-buffer, K+B-SB, AB_FP); pixels with "
            "more overflow, and where the trim point lies beyond the k nearest they are unresolved (magenta)",
};

inline constexpr ParameterSpec kSharedCounters{
    .id = "shared-counters",
    .flag = "shared-counters",
    .settingsKey = "render/sharedCounters",
    .kind = ParameterKind::Integer,
    .min = 1,
    .max = MethodParameters::kMaxSharedCounters,
    .defaultValue = MethodParameters{}.sharedCounters,
    .help = "S, the shared counters of the S-buffer's memory referencing: more counters mean less contention "
            "while counting but a longer prefix sum over them",
};

/// In MB, as users think of it; MethodParameters holds bytes (megabytes()).
inline constexpr ParameterSpec kMemoryBudget{
    .id = "memory-budget",
    .flag = "memory-budget",
    .settingsKey = "render/memoryBudgetMB",
    .kind = ParameterKind::Integer,
    .min = 0,
    .max = MethodParameters::kMaxMemoryBudgetMegabytes,
    .defaultValue = double(MethodParameters{}.memoryBudgetBytes),
    .unit = "MB",
    .help = "GPU memory the method's fragment storage may use; a method that would need more is not allocated "
            "(the view falls back to a leaner method, the command line stops with an error)",
    .minMeaning = "no limit",
};

inline constexpr std::array<const ParameterSpec*, 3> kTable{&kK, &kSharedCounters, &kMemoryBudget};
static_assert(isWellFormedTable(kTable));

/// The bytes of a budget of `megabytes` MB (0: none).
[[nodiscard]] constexpr std::size_t budgetBytes(int megabytes)
{
    return std::size_t(megabytes) * 1024 * 1024;
}

/// Throws std::invalid_argument naming the parameter when k, S or the budget lies
/// outside its row's range.
void validateMethodParameters(const MethodParameters& parameters);

} // namespace trimlab::render::method_parameters
