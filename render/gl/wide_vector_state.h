#pragma once
/// \file
/// The CPU's wide-vector state after a call into the OpenGL driver. Some drivers (NVIDIA's
/// 580 series) return from GL calls with the upper halves of the 256-bit vector registers
/// still in use; TrimLab's own code is compiled for baseline x86-64 (SSE2, no AVX), and on
/// Intel CPUs every SSE instruction then pays for merging those upper halves, which makes
/// CPU work after a frame several times slower (Mesa leaves nothing in use; the
/// measurements are in docs/gpu-results.md). The render layer therefore ends that state
/// wherever control goes back from the driver to CPU work: around every TrimRenderer and
/// GpuScene call that talks to the driver, after making a context current, and in the GUI
/// after each viewport paint and swap and whenever the event loop wakes.

#include <optional>

namespace trimlab::render {

/// Ends this thread's use of the upper vector halves (`vzeroupper`) where the CPU has AVX;
/// nothing elsewhere. Costs about a cycle; the registers' lower halves are kept.
void leaveWideVectorState() noexcept;

/// Whether this thread's upper vector halves are in use (XINUSE bit 2 of XGETBV 1); nullopt
/// where the CPU cannot tell (no AVX or no XGETBV 1, or not x86). For tests and probes.
[[nodiscard]] std::optional<bool> wideVectorStateInUse() noexcept;

/// Calls leaveWideVectorState() where it is made and where it goes out of scope (every return
/// and throw): a function that mixes CPU work (normals) with driver calls runs its CPU part
/// clean of what an earlier driver call left, and its caller's CPU work too.
class WideVectorStateScope {
public:
    WideVectorStateScope() noexcept { leaveWideVectorState(); }
    ~WideVectorStateScope() { leaveWideVectorState(); }
    WideVectorStateScope(const WideVectorStateScope&) = delete;
    WideVectorStateScope& operator=(const WideVectorStateScope&) = delete;
};

} // namespace trimlab::render
