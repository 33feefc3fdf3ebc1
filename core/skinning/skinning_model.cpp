#include "core/skinning/skinning_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

std::string vertexProblem(std::size_t v, const std::string& what)
{
    return "skinning weights: vertex " + std::to_string(v) + " " + what;
}

} // namespace

void requireConvexWeights(const SkinningWeights& weights, double tolerance)
{
    for (std::size_t v = 0; v < weights.vertices.size(); ++v) {
        const VertexInfluences& in = weights.vertices[v];
        if (in.count == 0 || in.count > kMaxInfluences)
            throw std::invalid_argument(vertexProblem(v, "has " + std::to_string(in.count) + " influences"));
        double sum = 0.0;
        for (std::uint32_t i = 0; i < in.count; ++i) {
            if (in.bones[i] >= weights.boneCount)
                throw std::invalid_argument(vertexProblem(v, "names bone " + std::to_string(in.bones[i]) + " of " +
                                                                 std::to_string(weights.boneCount)));
            if (!std::isfinite(in.weights[i]) || in.weights[i] < 0.0)
                throw std::invalid_argument(vertexProblem(v, "has the weight " + std::to_string(in.weights[i])));
            sum += in.weights[i];
        }
        if (std::abs(sum - 1.0) > tolerance)
            throw std::invalid_argument(vertexProblem(v, "has weights summing to " + std::to_string(sum)));
    }
}

VertexInfluences sparseInfluences(std::vector<std::pair<std::uint32_t, double>> influences, std::uint32_t fallbackBone,
                                  std::size_t limit)
{
    std::erase_if(influences, [](const auto& p) { return !(p.second > 0.0); });
    std::sort(influences.begin(), influences.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    VertexInfluences result;
    if (influences.empty()) {
        result.bones[0] = fallbackBone;
        result.weights[0] = 1.0;
        result.count = 1;
        return result;
    }
    result.count = std::uint32_t(std::min({influences.size(), std::max<std::size_t>(1, limit), kMaxInfluences}));
    double sum = 0.0;
    for (std::uint32_t i = 0; i < result.count; ++i)
        sum += influences[i].second;
    for (std::uint32_t i = 0; i < result.count; ++i) {
        result.bones[i] = influences[i].first;
        result.weights[i] = influences[i].second / sum;
    }
    return result;
}

SkinningWeights limitedInfluences(SkinningWeights weights, std::size_t limit)
{
    for (VertexInfluences& in : weights.vertices) {
        if (in.count <= limit || in.count > kMaxInfluences) // malformed ones are reported by the fit
            continue;
        std::vector<std::pair<std::uint32_t, double>> influences;
        for (std::uint32_t i = 0; i < in.count; ++i)
            influences.emplace_back(in.bones[i], in.weights[i]);
        in = sparseInfluences(std::move(influences), in.bones[0], limit);
    }
    return weights;
}

std::size_t SkinningModel::previousPose(std::size_t pose) const
{
    if (chain == SkinningChain::RestToPose || pose == restPose)
        return restPose;
    return pose > restPose ? pose - 1 : pose + 1;
}

bool restPoseMoves(const SkinningModel& model)
{
    if (model.method != SkinningMethod::Lbs || model.chain != SkinningChain::RestToPose ||
        model.restPose >= model.affine.size())
        return false;
    for (const Affine3& m : model.affine[model.restPose])
        if (!(m == Affine3{}))
            return true;
    return false;
}

std::vector<std::size_t> chainOrder(std::size_t poseCount, std::size_t restPose)
{
    std::vector<std::size_t> order;
    order.reserve(poseCount);
    for (std::size_t t = restPose; t < poseCount; ++t)
        order.push_back(t);
    for (std::size_t t = restPose; t-- > 0;)
        order.push_back(t);
    return order;
}

SkinningModel identitySkinningModel(SkinningMethod method, SkinningChain chain, std::size_t poseCount,
                                    std::size_t restPose, std::vector<glm::dvec3> restPositions,
                                    SkinningWeights weights, std::vector<glm::uvec3> triangles)
{
    if (weights.vertices.size() != restPositions.size())
        throw std::invalid_argument("skinning: " + std::to_string(weights.vertices.size()) + " weighted vertices for " +
                                    std::to_string(restPositions.size()) + " rest positions");
    if (restPose >= poseCount)
        throw std::invalid_argument("skinning: the rest pose " + std::to_string(restPose) + " is not one of " +
                                    std::to_string(poseCount) + " poses");
    requireConvexWeights(weights);
    SkinningModel model;
    model.method = method;
    model.chain = chain;
    model.restPose = restPose;
    model.triangles = std::move(triangles);
    model.restPositions = std::move(restPositions);
    const std::size_t bones = weights.boneCount;
    model.weights = std::move(weights);
    if (method == SkinningMethod::Lbs)
        model.affine.assign(poseCount, std::vector<Affine3>(bones));
    else
        model.rigid.assign(poseCount, std::vector<DualQuaternion>(bones));
    return model;
}

} // namespace trimlab
