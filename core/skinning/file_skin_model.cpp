#include "core/skinning/file_skin_model.h"

#include <glm/mat3x3.hpp>

namespace trimlab {

namespace {

bool affine(const glm::dmat4& m)
{
    return m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0;
}

std::optional<SkinningWeights> skinWeights(const AnimationSkin& skin)
{
    SkinningWeights weights;
    weights.boneCount = skin.jointCount;
    weights.vertices.reserve(skin.bindPositions.size());
    for (std::size_t v = 0; v < skin.bindPositions.size(); ++v) {
        std::vector<std::pair<std::uint32_t, double>> influences;
        for (std::size_t i = 0; i < skin.influences; ++i)
            if (skin.weights[v * skin.influences + i] > 0.0)
                influences.emplace_back(skin.joints[v * skin.influences + i], skin.weights[v * skin.influences + i]);
        if (influences.empty() || influences.size() > kMaxInfluences)
            return std::nullopt; // more joints than the GPU path blends: the poses as sampled
        weights.vertices.push_back(sparseInfluences(std::move(influences), 0, kMaxInfluences));
    }
    return weights;
}

} // namespace

std::optional<SkinningModel> fileSkinningModel(const MeshAnimation& animation)
{
    const AnimationSkin* skin = animation.skin.get();
    if (!skin || skin->bindPositions.size() != animation.vertexCount() ||
        skin->jointMatrices.size() != animation.poseCount())
        return std::nullopt;
    std::optional<SkinningWeights> weights = skinWeights(*skin);
    if (!weights)
        return std::nullopt;
    SkinningModel model;
    model.method = SkinningMethod::Lbs;
    model.chain = SkinningChain::RestToPose;
    model.restPose = animation.restPose;
    model.triangles = animation.triangles;
    model.restPositions = skin->bindPositions;
    model.weights = std::move(*weights);
    for (const std::vector<glm::dmat4>& pose : skin->jointMatrices) {
        if (pose.size() != skin->jointCount)
            return std::nullopt;
        std::vector<Affine3>& transforms = model.affine.emplace_back();
        for (const glm::dmat4& m : pose) {
            if (!affine(m))
                return std::nullopt;
            transforms.push_back({glm::dmat3(m), glm::dvec3(m[3])});
        }
    }
    return model;
}

} // namespace trimlab
