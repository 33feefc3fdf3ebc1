#include "render/frame_times.h"

#include <algorithm>

namespace trimlab::render {

double medianOf(std::vector<double> values, double empty)
{
    if (values.empty())
        return empty;
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2 == 1)
        return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(middle));
    return 0.5 * (lower + upper);
}

void FrameTimes::add(const FrameStats& stats)
{
    m_wallMs.push_back(stats.wallMilliseconds);
    if (stats.gpuMilliseconds >= 0.0)
        m_gpuMs.push_back(stats.gpuMilliseconds);
}

void FrameTimes::add(const FrameTimes& other)
{
    m_wallMs.insert(m_wallMs.end(), other.m_wallMs.begin(), other.m_wallMs.end());
    m_gpuMs.insert(m_gpuMs.end(), other.m_gpuMs.begin(), other.m_gpuMs.end());
}

bool FrameTimes::gpuTimed() const
{
    return !m_wallMs.empty() && m_gpuMs.size() == m_wallMs.size();
}

double FrameTimes::medianMilliseconds() const
{
    return gpuTimed() ? medianGpuMilliseconds() : medianWallMilliseconds();
}

double FrameTimes::medianGpuMilliseconds() const
{
    return medianOf(m_gpuMs, -1.0);
}

double FrameTimes::medianWallMilliseconds() const
{
    return medianOf(m_wallMs);
}

} // namespace trimlab::render
