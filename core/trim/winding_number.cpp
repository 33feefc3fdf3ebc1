#include "core/trim/winding_number.h"

#include "core/scene/world_geometry.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace trimlab {

double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const double la = glm::length(a);
    const double lb = glm::length(b);
    const double lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
    return 2.0 * std::atan2(numerator, denominator);
}

double solidAngleWindingNumber(const Scene& scene, const glm::dvec3& p)
{
    double total = 0.0;
    for (const SceneObject& object : scene.objects) {
        const std::vector<glm::dvec3> world = worldPositions(object);
        for (const glm::uvec3& t : object.mesh.triangles)
            total += triangleSolidAngle(world[t[0]] - p, world[t[1]] - p, world[t[2]] - p);
    }
    return total / (4.0 * glm::pi<double>());
}

} // namespace trimlab
