#include "core/surface/nurbs_sampling.h"

#include <algorithm>
#include <cmath>

namespace trimlab {

std::vector<double> tessellationParameters(const std::vector<double>& knots, int segments, bool closed)
{
    std::vector<double> breaks(knots);
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const std::size_t spans = breaks.size() - 1;
    const double domain = breaks.back() - breaks.front();
    const long minimum = closed ? long((3 + spans - 1) / spans) : 1L;
    std::vector<double> params;
    for (std::size_t s = 0; s < spans; ++s) {
        const double a = breaks[s], b = breaks[s + 1];
        const long count = std::max(minimum, std::lround(double(segments) * (b - a) / domain));
        for (long k = 0; k < count; ++k)
            params.push_back(k == 0 ? a : a + (b - a) * (double(k) / double(count)));
    }
    params.push_back(breaks.back());
    return params;
}

} // namespace trimlab
