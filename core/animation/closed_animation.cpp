#include "core/animation/closed_animation.h"

#include "core/mesh/hole_fans.h"

#include <string>

namespace trimlab {

MeshAnimation closeAnimationHoles(const MeshAnimation& animation, HoleClosing* closing)
{
    const HoleFans fans = holeFans(animation.triangles, animation.vertexCount());
    HoleClosing report{fans.loops.size(), fans.triangles.size(), {}, 0};
    if (fans.empty()) {
        if (closing)
            *closing = report;
        return animation;
    }
    MeshAnimation closed = animation;
    closed.skin = nullptr; // its bind positions lack the centres: the poses stand alone
    for (std::size_t p = 0; p < closed.poses.size(); ++p) {
        closed.poses[p] = withHoleCentres(fans, animation.poses[p]);
        const std::optional<FanCrossing> crossing = firstFanCrossing(fans, animation.triangles, closed.poses[p]);
        if (!crossing)
            continue;
        if (report.crossing.empty())
            report.crossing = "pose " + std::to_string(p) + ": " + fanCrossingMessage(fans, *crossing);
        ++report.crossingMeshes;
    }
    closed.triangles.insert(closed.triangles.end(), fans.triangles.begin(), fans.triangles.end());
    if (closing)
        *closing = report;
    return closed;
}

} // namespace trimlab
