#include "core/mesh/corner_angle.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace trimlab {

double cornerAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 u = b - a;
    const glm::dvec3 v = c - a;
    const double lu = glm::length(u);
    const double lv = glm::length(v);
    if (lu == 0.0 || lv == 0.0)
        return 0.0;
    return std::acos(glm::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
}

} // namespace trimlab
