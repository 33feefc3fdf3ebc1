#include "core/animation/animation_skin.h"

namespace trimlab {

AnimationSkin keepSkinVertices(const AnimationSkin& skin, const std::vector<std::size_t>& kept)
{
    AnimationSkin result;
    result.jointCount = skin.jointCount;
    result.influences = skin.influences;
    result.jointMatrices = skin.jointMatrices;
    result.bindPositions.reserve(kept.size());
    for (std::size_t v : kept) {
        result.bindPositions.push_back(skin.bindPositions[v]);
        for (std::size_t i = 0; i < skin.influences; ++i) {
            result.joints.push_back(skin.joints[v * skin.influences + i]);
            result.weights.push_back(skin.weights[v * skin.influences + i]);
        }
    }
    return result;
}

} // namespace trimlab
