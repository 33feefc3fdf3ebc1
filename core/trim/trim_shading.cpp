#include "trim/trim_shading.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace trimlab {

glm::vec3 shadeTrimPoint(int facing, const glm::dvec3& normal, const glm::dvec3& toViewer)
{
    const glm::vec3 base = facing > 0 ? kFrontFacingColor : kBackFacingColor;
    // Two-sided: the viewer sees whichever side faces it.
    const float diffuse = static_cast<float>(std::abs(glm::dot(normal, toViewer)));
    return base * (kAmbient + (1.0f - kAmbient) * diffuse);
}

} // namespace trimlab
