#include "render/gl/wide_vector_state.h"

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>

#include <cstdint>
#endif

namespace trimlab::render {

#if defined(__x86_64__) || defined(__i386__)
namespace {

bool cpuHasAvx() noexcept
{
    static const bool avx = __builtin_cpu_supports("avx");
    return avx;
}

// CPUID leaf 0xD, sub-leaf 1, EAX bit 2: XGETBV with ECX = 1 reports the state in use.
bool cpuReportsStateInUse() noexcept
{
    static const bool reports = [] {
        unsigned a = 0, b = 0, c = 0, d = 0;
        return cpuHasAvx() && __get_cpuid_count(0xd, 1, &a, &b, &c, &d) != 0 && (a & 4u) != 0;
    }();
    return reports;
}

} // namespace

void leaveWideVectorState() noexcept
{
    // The instruction is written out rather than taken from <immintrin.h>: the intrinsic
    // needs the file compiled for AVX, and the rest of the binary must run without it.
    if (cpuHasAvx())
        asm volatile("vzeroupper" ::: "memory");
}

std::optional<bool> wideVectorStateInUse() noexcept
{
    if (!cpuReportsStateInUse())
        return std::nullopt;
    std::uint32_t low = 0, high = 0;
    asm volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(1u));
    constexpr std::uint32_t kUpperHalvesInUse = 1u << 2; // XCR0 component 2: the YMM upper halves
    return (low & kUpperHalvesInUse) != 0;
}

#else

void leaveWideVectorState() noexcept
{
}

std::optional<bool> wideVectorStateInUse() noexcept
{
    return std::nullopt;
}

#endif

} // namespace trimlab::render
