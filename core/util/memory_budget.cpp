#include "core/util/memory_budget.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include <sys/resource.h>
#include <unistd.h>

namespace trimlab {

namespace {

/// $TRIMLAB_MEMORY_BUDGET as bytes, or 0 when unset or unreadable.
std::uint64_t budgetFromEnvironment()
{
    const char* text = std::getenv("TRIMLAB_MEMORY_BUDGET");
    if (!text || !*text)
        return 0;
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || !(value > 0.0) || value > 1e18)
        return 0;
    double scale = 1.0;
    switch (std::toupper(static_cast<unsigned char>(*end))) {
    case 'K':
        scale = 1024.0;
        break;
    case 'M':
        scale = 1024.0 * 1024.0;
        break;
    case 'G':
        scale = 1024.0 * 1024.0 * 1024.0;
        break;
    case '\0':
        break;
    default:
        return 0;
    }
    return std::uint64_t(value * scale);
}

std::uint64_t halfThePhysicalMemory()
{
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0)
        return std::uint64_t(4) << 30; // unknown: a conservative 4 GiB
    return std::uint64_t(pages) * std::uint64_t(pageSize) / 2;
}

/// Half of the address space this process may still map under its RLIMIT_AS (prlimit
/// --as, ulimit -v: a batch farm's memory cap), or nullopt without such a limit. The
/// mapped size is read from /proc/self/statm; half, because an estimate counts the data
/// and not the allocator's and the libraries' own mappings.
std::optional<std::uint64_t> halfTheAddressSpaceLeft()
{
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return std::nullopt;
    unsigned long long pages = 0;
    if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%llu", &pages) != 1)
            pages = 0;
        std::fclose(statm);
    }
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    const std::uint64_t mapped = pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0;
    const std::uint64_t cap = std::uint64_t(limit.rlim_cur);
    return cap > mapped ? (cap - mapped) / 2 : 0;
}

/// Where the budget comes from, for the refusal's message.
std::string budgetSource(bool limitedByAddressSpace)
{
    if (budgetFromEnvironment() > 0)
        return "set by TRIMLAB_MEMORY_BUDGET";
    if (limitedByAddressSpace)
        return "half of what this process's memory limit (ulimit -v) leaves; raise the limit to allow more";
    return "half of this machine's memory; set TRIMLAB_MEMORY_BUDGET to change it";
}

} // namespace

std::uint64_t memoryBudgetBytes()
{
    const std::uint64_t chosen = budgetFromEnvironment();
    if (chosen > 0)
        return chosen;
    const std::uint64_t physical = halfThePhysicalMemory();
    const std::optional<std::uint64_t> addressSpace = halfTheAddressSpaceLeft();
    return addressSpace ? std::min(physical, *addressSpace) : physical;
}

std::string formatMemory(std::uint64_t bytes)
{
    static const char* const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    double value = double(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 4) {
        value /= 1024.0;
        ++unit;
    }
    char text[48];
    if (unit == 0)
        std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    else
        std::snprintf(text, sizeof text, "%.1f %s", value, units[unit]);
    return text;
}

void requireMemory(std::uint64_t bytes, const std::string& what, const std::string& advice)
{
    const std::uint64_t budget = memoryBudgetBytes();
    if (bytes <= budget)
        return;
    const std::string source = budgetSource(budget < halfThePhysicalMemory());
    throw MemoryBudgetError(what + " needs about " + formatMemory(bytes) + ", more than the memory budget of " +
                            formatMemory(budget) + " (" + source + "); " + advice);
}

} // namespace trimlab
