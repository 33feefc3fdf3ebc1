#include "core/skinning/skinning_propagation.h"

#include "core/skinning/skinning_pose_fit.h"
#include "core/skinning/skinning_reconstruction.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

void requirePose(const SkinningModel& model, std::size_t pose)
{
    if (pose >= model.poseCount())
        throw std::invalid_argument("skinning edit: pose " + std::to_string(pose) + " of " +
                                    std::to_string(model.poseCount()));
}

void requireBone(const SkinningModel& model, std::size_t pose, std::size_t bone)
{
    requirePose(model, pose);
    if (bone >= model.boneCount())
        throw std::invalid_argument("skinning edit: bone " + std::to_string(bone) + " of " +
                                    std::to_string(model.boneCount()));
}

// The poses from `pose` back towards the rest pose (excluding it), latest first.
std::vector<std::size_t> pathToRest(const SkinningModel& model, std::size_t pose)
{
    std::vector<std::size_t> path;
    for (std::size_t t = pose; t != model.restPose; t = model.previousPose(t))
        path.push_back(t);
    return path;
}

} // namespace

SkinningModel editPose(const SkinningModel& model, std::size_t pose, std::span<const glm::dvec3> positions,
                       const PoseFitOptions& options)
{
    requirePose(model, pose);
    if (positions.size() != model.vertexCount())
        throw std::invalid_argument("skinning edit: " + std::to_string(positions.size()) + " positions for " +
                                    std::to_string(model.vertexCount()) + " vertices");
    SkinningModel edited = model;
    if (pose == model.restPose) {
        edited.restPositions.assign(positions.begin(), positions.end());
        return edited;
    }
    const PosePositions source = reconstructPose(model, model.previousPose(pose));
    const SkinningPoseFitter fitter(edited.weights, options);
    fitter.fitPose(edited, pose, source, positions);
    return edited;
}

SkinningModel setBoneTransform(const SkinningModel& model, std::size_t pose, std::size_t bone, const Affine3& transform)
{
    requireBone(model, pose, bone);
    if (model.method != SkinningMethod::Lbs)
        throw std::invalid_argument("skinning edit: an affine bone transform for a DQS model");
    SkinningModel edited = model;
    edited.affine[pose][bone] = transform;
    return edited;
}

SkinningModel setBoneTransform(const SkinningModel& model, std::size_t pose, std::size_t bone,
                               const DualQuaternion& transform)
{
    requireBone(model, pose, bone);
    if (model.method != SkinningMethod::Dqs)
        throw std::invalid_argument("skinning edit: a dual quaternion bone transform for an LBS model");
    SkinningModel edited = model;
    edited.rigid[pose][bone] = normalized(transform);
    return edited;
}

Affine3 chainProduct(const SkinningModel& model, std::size_t vertex, std::size_t later, std::size_t earlier)
{
    const std::vector<std::size_t> path = pathToRest(model, later);
    std::size_t stop = 0; // number of path entries from `later` down to `earlier`
    while (stop < path.size() && path[stop] != earlier)
        ++stop;
    if (stop == path.size())
        return {};
    Affine3 product;
    for (std::size_t i = stop + 1; i-- > 0;)
        product = compose(blendedTransform(model, path[i], vertex), product);
    return product;
}

Affine3 propagatedRestToPose(const SkinningModel& model, std::size_t vertex, std::size_t pose, std::size_t edited,
                             const Affine3& editedBlend)
{
    const std::vector<std::size_t> path = pathToRest(model, pose); // pose … edited … first
    std::size_t at = 0;
    while (at < path.size() && path[at] != edited)
        ++at;
    if (at == path.size())
        throw std::invalid_argument("skinning edit: pose " + std::to_string(pose) + " does not follow pose " +
                                    std::to_string(edited));
    const Affine3 after = at > 0 ? chainProduct(model, vertex, pose, path[at - 1]) : Affine3{};
    const Affine3 before = at + 1 < path.size() ? chainProduct(model, vertex, path[at + 1], path.back()) : Affine3{};
    return compose(after, compose(editedBlend, before));
}

} // namespace trimlab
