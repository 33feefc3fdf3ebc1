#include "core/scene/scene.h"

#include <cmath>

namespace trimlab {

Bounds Scene::worldBounds() const
{
    Bounds b;
    for (const SceneObject& object : objects) {
        for (const glm::vec3& p : object.mesh.positions) {
            const glm::dvec4 w = object.modelMatrix * glm::dvec4(glm::dvec3(p), 1.0);
            if (std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z))
                b.extend(glm::dvec3(w));
        }
    }
    return b;
}

std::size_t Scene::triangleCount() const
{
    std::size_t n = 0;
    for (const SceneObject& object : objects)
        n += object.mesh.triangleCount();
    return n;
}

} // namespace trimlab
