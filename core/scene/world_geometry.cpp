#include "core/scene/world_geometry.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

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

namespace {

constexpr double kFloatMax = double(std::numeric_limits<float>::max());

std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

bool fitsFloat(double value)
{
    return std::isfinite(value) && std::abs(value) <= kFloatMax;
}

} // namespace

std::string placementProblem(const SceneObject& object)
{
    const std::string range = ", beyond single precision (±" + numberText(kFloatMax) + ")";
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!fitsFloat(object.modelMatrix[c][r]))
                return "its model matrix entry [" + std::to_string(c) + "][" + std::to_string(r) + "] is " +
                       numberText(object.modelMatrix[c][r]) + range;
    const Bounds box = computeBounds(object.mesh);
    if (!box.valid())
        return {};
    static constexpr char kAxes[] = "xyz";
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 local((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                               (corner & 4) ? box.max.z : box.min.z);
        const glm::dvec4 world = object.modelMatrix * glm::dvec4(local, 1.0);
        for (int axis = 0; axis < 3; ++axis)
            if (!fitsFloat(world[axis]))
                return std::string("it places a vertex at ") + kAxes[axis] + " = " + numberText(world[axis]) + range;
    }
    return {};
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
