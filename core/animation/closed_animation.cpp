#include "core/animation/closed_animation.h"

#include "core/mesh/hole_fans.h"

#include <stdexcept>
#include <string>

namespace trimlab {

MeshAnimation closeAnimationHoles(const MeshAnimation& animation, HoleClosing* closing)
{
    const HoleFans fans = holeFans(animation.triangles, animation.vertexCount());
    if (closing)
        *closing = HoleClosing{fans.loops.size(), fans.triangles.size()};
    if (fans.empty())
        return animation;
    MeshAnimation closed = animation;
    closed.skin = nullptr; // its bind positions lack the centres: the poses stand alone
    for (std::size_t p = 0; p < closed.poses.size(); ++p) {
        closed.poses[p] = withHoleCentres(fans, animation.poses[p]);
        if (const std::optional<FanCrossing> crossing = firstFanCrossing(fans, animation.triangles, closed.poses[p]))
            throw std::invalid_argument("pose " + std::to_string(p) + ": " + fanCrossingMessage(fans, *crossing));
    }
    closed.triangles.insert(closed.triangles.end(), fans.triangles.begin(), fans.triangles.end());
    return closed;
}

} // namespace trimlab
