#pragma once
/// \file
/// The time per frame of a method, as `trimlab render --repeat`, `trimlab bench` and the
/// GUI's method comparison report it: the median over repeated frames of the GPU time
/// (GL_TIME_ELAPSED) when the driver gave a plausible one for every frame, else of the
/// wall-clock time of TrimRenderer::render (which includes waiting for the GPU).

#include "render/trim_renderer.h"

#include <string_view>
#include <vector>

namespace trimlab::render {

class FrameTimes {
public:
    /// Records the times of one frame (TrimRenderer::lastStats()).
    void add(const FrameStats& stats);
    /// Adds every frame of `other`.
    void add(const FrameTimes& other);

    [[nodiscard]] int frames() const { return int(m_wallMs.size()); }
    /// True when there is at least one frame and every frame has a GPU time.
    [[nodiscard]] bool gpuTimed() const;
    /// The median GPU time if gpuTimed(), else the median wall time; 0 without frames.
    [[nodiscard]] double medianMilliseconds() const;
    /// Medians of the GPU times (frames without one left out; negative when none) and of
    /// the wall times (0 without frames). Even counts give the mean of the middle two.
    [[nodiscard]] double medianGpuMilliseconds() const;
    [[nodiscard]] double medianWallMilliseconds() const;
    /// "GPU" or "wall": what medianMilliseconds() measures.
    [[nodiscard]] std::string_view source() const { return gpuTimed() ? "GPU" : "wall"; }

private:
    std::vector<double> m_gpuMs; ///< plausible GPU times only
    std::vector<double> m_wallMs;
};

/// The median of `values` (mean of the middle two for even counts); `empty` without values.
[[nodiscard]] double medianOf(std::vector<double> values, double empty = 0.0);

} // namespace trimlab::render
