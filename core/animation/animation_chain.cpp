#include "core/animation/animation_chain.h"

#include <stdexcept>
#include <string>

namespace trimlab {

std::string_view poseReferenceName(PoseReference reference)
{
    return reference == PoseReference::Rest ? "rest" : "previous";
}

std::optional<PoseReference> parsePoseReference(std::string_view name)
{
    for (PoseReference reference : {PoseReference::Rest, PoseReference::Previous})
        if (name == poseReferenceName(reference))
            return reference;
    return std::nullopt;
}

std::vector<std::size_t> chainPoses(std::size_t restPose, std::size_t pose, PoseReference reference)
{
    if (pose == restPose)
        return {restPose};
    if (reference == PoseReference::Rest)
        return {restPose, pose};
    // Poses before the rest pose are reached backwards from it, as playing backwards from
    // the rest pose would.
    std::vector<std::size_t> poses;
    for (std::size_t p = restPose;; p = pose > restPose ? p + 1 : p - 1) {
        poses.push_back(p);
        if (p == pose)
            break;
    }
    return poses;
}

std::optional<DynamicChain> animationChain(const MeshAnimation& animation, std::size_t pose, PoseReference reference,
                                           DynamicRule rule, StaticRule baseRule)
{
    if (pose >= animation.poseCount())
        throw std::out_of_range("pose " + std::to_string(pose) + " does not exist; the animation has " +
                                std::to_string(animation.poseCount()) + " poses");
    const std::size_t rest = animation.restPose;
    if (pose == rest)
        return std::nullopt;
    std::vector<std::vector<glm::vec3>> frames;
    for (std::size_t p : chainPoses(rest, pose, reference))
        frames.push_back(animation.poses[p]);
    const std::vector<DynamicRule> rules(frames.size() - 1, rule);
    return makeDynamicChain(animation.triangles, frames, rules, baseRule);
}

} // namespace trimlab
