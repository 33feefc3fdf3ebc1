#pragma once
/// \file
/// The memory one CPU-side job may take before it starts: the CPU reference render, Loop
/// subdivision, a version-2 project's tessellation, loading an animation. Each estimates
/// what it will allocate and refuses beyond the budget with a message that says how much,
/// against what, and what to change, instead of being killed by the system halfway (the
/// GPU path has the same kind of check against the driver's limits and the Render panel's
/// budget).
///
/// The budget: $TRIMLAB_MEMORY_BUDGET when set (bytes, or a number with K, M or G: "512M",
/// "8G"), else half of this machine's physical memory or, when the process runs under an
/// address-space limit (prlimit --as, ulimit -v) that leaves less, half of what that limit
/// leaves: under a batch farm's cap the estimate refuses with a message before the system
/// refuses an allocation halfway.

#include <cstdint>
#include <stdexcept>
#include <string>

namespace trimlab {

/// Thrown by requireMemory; what() is the whole message.
class MemoryBudgetError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The budget in bytes (see the file comment), read each time so that a test or a user
/// can change it while the program runs.
[[nodiscard]] std::uint64_t memoryBudgetBytes();

/// "1.5 GiB", "640 MiB", "12 KiB", "512 bytes".
[[nodiscard]] std::string formatMemory(std::uint64_t bytes);

/// Throws MemoryBudgetError when `bytes` exceeds the budget: "<what> needs about 12.0 GiB,
/// more than the memory budget of 8.0 GiB (half of this machine's memory; set
/// TRIMLAB_MEMORY_BUDGET to change it); <advice>".
void requireMemory(std::uint64_t bytes, const std::string& what, const std::string& advice);

} // namespace trimlab
