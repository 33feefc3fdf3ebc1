#include "core/skeleton/half_sphere_directions.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

std::vector<glm::dvec3> halfSphereDirections(int count)
{
    std::vector<glm::dvec3> directions;
    // Equal steps in z give equal areas on the sphere; the golden angle between
    // consecutive points keeps them from lining up.
    const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = (i + 0.5) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        directions.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
    }
    return directions;
}

} // namespace trimlab
