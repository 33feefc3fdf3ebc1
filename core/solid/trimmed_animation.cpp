#include "core/solid/trimmed_animation.h"

#include "core/catalog/pose_scene.h"
#include "core/util/parallel_for.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

std::string trimmedPoseName(std::size_t pose)
{
    char name[32];
    std::snprintf(name, sizeof name, "pose_%04zu", pose);
    return name;
}

namespace {

TrimmedSolid trimmedPose(const MeshAnimation& animation, std::size_t pose, const TrimSettings& settings,
                         const TaskControl& control)
{
    const LoadedScene scene = animationPoseScene(animation, pose, "pose", "pose " + std::to_string(pose));
    if (!scene.trimmable())
        throw std::invalid_argument("pose " + std::to_string(pose) + ": " + scene.trimUnavailableReason());
    return cutTrimmedSolid(scene.scene, settings, control);
}

} // namespace

void trimAnimationPoses(const MeshAnimation& animation, std::size_t first, std::size_t last,
                        const TrimSettings& settings, const TrimmedPoseSink& each, const TaskControl& control)
{
    const std::size_t count = animation.poseCount();
    if (first > last || last >= count)
        throw std::invalid_argument("poses " + std::to_string(first) + " to " + std::to_string(last) +
                                    ": the animation has " + std::to_string(count) + " poses (0 to " +
                                    std::to_string(count == 0 ? 0 : count - 1) + ")");
    const std::size_t total = last - first + 1;
    control.report("poses", 0, total);
    TaskControl inner;
    inner.stop = control.stop; // the poses report progress; each pose only listens for Cancel
    // A batch of poses at a time, one per core, delivered in order: at most a batch of
    // solids is held at once.
    const std::size_t batch = effectiveThreadCount(0, total);
    for (std::size_t start = first; start <= last; start += batch) {
        const std::size_t size = std::min(batch, last + 1 - start);
        std::vector<std::optional<TrimmedSolid>> solids(size);
        // Each pose's failure is kept, so that the first pose in order that fails is the
        // one reported (and those before it are delivered), whichever thread failed first.
        std::vector<std::exception_ptr> failures(size);
        parallelFor(
            size, unsigned(size),
            [&](std::size_t i) {
                try {
                    solids[i] = trimmedPose(animation, start + i, settings, inner);
                } catch (...) {
                    failures[i] = std::current_exception();
                }
            },
            inner);
        for (std::size_t i = 0; i < size; ++i) {
            if (failures[i])
                std::rethrow_exception(failures[i]);
            control.throwIfCancelled();
            each(start + i, *solids[i]);
            solids[i].reset();
            control.report("poses", start + i - first + 1, total);
        }
    }
}

} // namespace trimlab
