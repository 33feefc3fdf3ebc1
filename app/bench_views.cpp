#include "app/bench_views.h"

#include <glm/trigonometric.hpp>

#include <cmath>

namespace trimlab::app {

std::vector<Camera> benchViews(const Bounds& bounds, double aspect, int count)
{
    std::vector<Camera> views;
    if (!bounds.valid() || count < 1)
        return views;
    const double elevation = glm::radians(kBenchViewElevationDegrees);
    for (int i = 0; i < count; ++i) {
        const double azimuth = glm::radians(kBenchViewFirstAzimuthDegrees + 360.0 * double(i) / double(count));
        // From the eye toward the centre: down by the elevation, around y by the azimuth.
        const glm::dvec3 toCentre{-std::cos(elevation) * std::sin(azimuth), -std::sin(elevation),
                                  -std::cos(elevation) * std::cos(azimuth)};
        views.push_back(fitCamera(bounds, aspect, toCentre));
    }
    return views;
}

} // namespace trimlab::app
