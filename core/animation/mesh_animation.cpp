#include "core/animation/mesh_animation.h"

#include <stdexcept>

namespace trimlab {

TriangleMesh MeshAnimation::poseMesh(std::size_t index) const
{
    TriangleMesh mesh;
    mesh.positions = poses.at(index);
    mesh.triangles = triangles;
    return mesh;
}

void requireWellFormed(const MeshAnimation& animation)
{
    auto fail = [](const std::string& reason) { throw std::invalid_argument("mesh animation: " + reason); };
    if (animation.poses.empty())
        fail("it has no poses");
    if (animation.triangles.empty())
        fail("it has no triangles");
    const std::size_t vertexCount = animation.vertexCount();
    for (std::size_t p = 0; p < animation.poses.size(); ++p) {
        if (animation.poses[p].size() != vertexCount)
            fail("pose " + std::to_string(p) + " has " + std::to_string(animation.poses[p].size()) +
                 " vertices, but pose 0 has " + std::to_string(vertexCount));
    }
    for (std::size_t f = 0; f < animation.triangles.size(); ++f) {
        const glm::uvec3& t = animation.triangles[f];
        if (t.x >= vertexCount || t.y >= vertexCount || t.z >= vertexCount)
            fail("face " + std::to_string(f) + " references a vertex ≥ " + std::to_string(vertexCount));
    }
    if (animation.restPose >= animation.poses.size())
        fail("the rest pose " + std::to_string(animation.restPose) + " does not exist");
    if (!animation.poseNames.empty() && animation.poseNames.size() != animation.poses.size())
        fail("it has " + std::to_string(animation.poseNames.size()) + " pose names for " +
             std::to_string(animation.poses.size()) + " poses");
    if (!animation.poseTimes.empty() && animation.poseTimes.size() != animation.poses.size())
        fail("it has " + std::to_string(animation.poseTimes.size()) + " pose times for " +
             std::to_string(animation.poses.size()) + " poses");
}

} // namespace trimlab
