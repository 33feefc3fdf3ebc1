#include "core/animation/closed_animation.h"

#include "core/mesh/hole_fans.h"

namespace trimlab {

MeshAnimation closeAnimationHoles(const MeshAnimation& animation)
{
    const HoleFans fans = holeFans(animation.triangles, animation.vertexCount());
    if (fans.empty())
        return animation;
    MeshAnimation closed = animation;
    closed.triangles.insert(closed.triangles.end(), fans.triangles.begin(), fans.triangles.end());
    for (std::vector<glm::vec3>& pose : closed.poses)
        pose = withHoleCentres(fans, pose);
    return closed;
}

} // namespace trimlab
