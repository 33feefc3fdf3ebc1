#include "core/design/control_point_pick.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trimlab {

std::optional<std::uint32_t> nearestPoint(glm::dvec2 cursor, std::span<const std::optional<glm::dvec2>> points,
                                          double maxDistance)
{
    std::optional<std::uint32_t> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i])
            continue;
        const glm::dvec2 d = *points[i] - cursor;
        const double distance = std::hypot(d.x, d.y);
        if (distance <= maxDistance && distance < bestDistance) {
            best = std::uint32_t(i);
            bestDistance = distance;
        }
    }
    return best;
}

std::vector<std::uint32_t> clickedSelection(std::vector<std::uint32_t> selection, std::optional<std::uint32_t> picked,
                                            bool toggle)
{
    if (!toggle)
        return picked ? std::vector<std::uint32_t>{*picked} : std::vector<std::uint32_t>{};
    if (!picked)
        return selection;
    const auto at = std::lower_bound(selection.begin(), selection.end(), *picked);
    if (at != selection.end() && *at == *picked)
        selection.erase(at);
    else
        selection.insert(at, *picked);
    return selection;
}

} // namespace trimlab
