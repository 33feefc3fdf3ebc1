#include "core/skinning/skinning_reconstruction.h"

#include <array>
#include <cassert>

namespace trimlab {

Affine3 blendedTransform(const SkinningModel& model, std::size_t pose, std::size_t vertex)
{
    const VertexInfluences& in = model.weights.vertices[vertex];
    if (model.method == SkinningMethod::Lbs) {
        const std::vector<Affine3>& q = model.affine[pose];
        Affine3 sum{glm::dmat3(0.0), glm::dvec3(0.0)};
        for (std::uint32_t i = 0; i < in.count; ++i)
            sum = weightedSum(sum, q[in.bones[i]], in.weights[i]);
        return sum;
    }
    const std::vector<DualQuaternion>& q = model.rigid[pose];
    std::array<DualQuaternion, kMaxInfluences> transforms;
    for (std::uint32_t i = 0; i < in.count; ++i)
        transforms[i] = q[in.bones[i]];
    const DualQuaternion blend = blendDualQuaternions(std::span(transforms.data(), in.count),
                                                      std::span(in.weights.data(), in.count), transforms[0]);
    return toAffine(blend);
}

std::vector<PosePositions> reconstructPoses(const SkinningModel& model)
{
    std::vector<PosePositions> poses(model.poseCount());
    const bool restMoves = restPoseMoves(model);
    for (std::size_t t : chainOrder(model.poseCount(), model.restPose)) {
        if (t == model.restPose) {
            poses[t] = model.restPositions;
            if (restMoves)
                for (std::size_t j = 0; j < poses[t].size(); ++j)
                    poses[t][j] = blendedTransform(model, t, j).apply(model.restPositions[j]);
            continue;
        }
        // Rest-to-pose transforms act on the rest positions (the same as the rest pose's
        // reconstruction, unless the rest pose moves).
        const PosePositions& previous =
            model.chain == SkinningChain::RestToPose ? model.restPositions : poses[model.previousPose(t)];
        PosePositions& current = poses[t];
        current.resize(model.vertexCount());
        for (std::size_t j = 0; j < current.size(); ++j)
            current[j] = blendedTransform(model, t, j).apply(previous[j]);
    }
    return poses;
}

namespace {

// The poses whose transforms carry the rest positions to `pose`, last first: `pose`, its
// previous pose, ... down to (excluding) the rest pose — or including it when it moves.
std::vector<std::size_t> pathToPose(const SkinningModel& model, std::size_t pose)
{
    std::vector<std::size_t> path;
    for (std::size_t t = pose; t != model.restPose; t = model.previousPose(t))
        path.push_back(t);
    if (restPoseMoves(model) && pose == model.restPose)
        path.push_back(pose);
    return path;
}

} // namespace

PosePositions reconstructPose(const SkinningModel& model, std::size_t pose)
{
    const std::vector<std::size_t> path = pathToPose(model, pose);
    PosePositions positions = model.restPositions;
    for (auto it = path.rbegin(); it != path.rend(); ++it)
        for (std::size_t j = 0; j < positions.size(); ++j)
            positions[j] = blendedTransform(model, *it, j).apply(positions[j]);
    return positions;
}

void vertexRestToPose(const SkinningModel& model, std::size_t vertex, std::vector<Affine3>& out)
{
    out.assign(model.poseCount(), Affine3{});
    for (std::size_t t : chainOrder(model.poseCount(), model.restPose))
        if (t != model.restPose)
            out[t] = compose(blendedTransform(model, t, vertex), out[model.previousPose(t)]);
    if (restPoseMoves(model)) // rest-to-pose: no pose composes the rest pose's own transform
        out[model.restPose] = blendedTransform(model, model.restPose, vertex);
}

std::vector<Affine3> restToPoseTransforms(const SkinningModel& model, std::size_t pose)
{
    std::vector<Affine3> result(model.vertexCount());
    const std::vector<std::size_t> path = pathToPose(model, pose);
    for (std::size_t j = 0; j < result.size(); ++j)
        for (auto it = path.rbegin(); it != path.rend(); ++it)
            result[j] = compose(blendedTransform(model, *it, j), result[j]);
    return result;
}

PosePositions toDoublePositions(const std::vector<glm::vec3>& positions)
{
    return PosePositions(positions.begin(), positions.end());
}

} // namespace trimlab
