#include "core/deform/angle_attenuation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace trimlab::deform {

double angleAttenuation(const glm::dvec3& vertexNormal, const glm::dvec3& anchorNormal, const glm::dvec3& dragDirection)
{
    const double deficit = glm::dot(anchorNormal - vertexNormal, dragDirection);
    return glm::clamp(1.0 - 0.5 * deficit, 0.0, 1.0);
}

} // namespace trimlab::deform
