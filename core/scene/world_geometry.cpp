#include "core/scene/world_geometry.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace trimlab {

std::vector<glm::dvec3> worldPositions(const SceneObject& object)
{
    std::vector<glm::dvec3> world;
    world.reserve(object.mesh.positions.size());
    for (const glm::vec3& p : object.mesh.positions) {
        const glm::dvec4 h = object.modelMatrix * glm::dvec4(glm::dvec3(p), 1.0);
        world.push_back(h.w == 1.0 ? glm::dvec3(h) : glm::dvec3(h) / h.w);
    }
    return world;
}

std::vector<glm::dvec3> worldNormals(const SceneObject& object)
{
    const glm::dmat3 linear(object.modelMatrix);
    const double det = glm::determinant(linear);
    const glm::dmat3 normalMatrix = det != 0.0 ? glm::transpose(glm::inverse(linear)) : glm::dmat3(0.0);
    const std::vector<glm::vec3> local = vertexNormals(object.mesh);
    std::vector<glm::dvec3> world;
    world.reserve(local.size());
    for (const glm::vec3& n : local)
        world.push_back(normalMatrix * glm::dvec3(n));
    return world;
}

} // namespace trimlab
