#include "core/util/memory_budget.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

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

} // namespace

std::uint64_t memoryBudgetBytes()
{
    const std::uint64_t chosen = budgetFromEnvironment();
    return chosen > 0 ? chosen : halfThePhysicalMemory();
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
    const std::string source = budgetFromEnvironment() > 0 ? "set by TRIMLAB_MEMORY_BUDGET"
                                                           : "half of this machine's memory; set TRIMLAB_MEMORY_BUDGET "
                                                             "to change it";
    throw MemoryBudgetError(what + " needs about " + formatMemory(bytes) + ", more than the memory budget of " +
                            formatMemory(budget) + " (" + source + "); " + advice);
}

} // namespace trimlab
