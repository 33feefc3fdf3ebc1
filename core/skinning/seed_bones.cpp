#include "core/skinning/seed_bones.h"

#include "core/skinning/skinning_fitter.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace trimlab {

VertexLabeling nearestSeedLabels(const std::vector<glm::vec3>& positions, std::size_t count)
{
    std::vector<std::size_t> seeds{0};
    std::vector<double> distance(positions.size(), std::numeric_limits<double>::infinity());
    VertexLabeling labeling;
    labeling.labels.assign(positions.size(), 0u);
    labeling.count = std::uint32_t(count);
    for (std::size_t s = 0; s < count; ++s) {
        const glm::dvec3 seed(positions[seeds.back()]);
        for (std::size_t v = 0; v < positions.size(); ++v) {
            const double d = glm::length(glm::dvec3(positions[v]) - seed);
            if (d < distance[v]) {
                distance[v] = d;
                labeling.labels[v] = std::uint32_t(s);
            }
        }
        if (s + 1 < count)
            seeds.push_back(std::size_t(std::max_element(distance.begin(), distance.end()) - distance.begin()));
    }
    return labeling;
}

SkinningModel seedBoneModel(const MeshAnimation& animation, std::size_t bones, SkinningMethod method,
                            SkinningChain chain)
{
    SkinningFitOptions options;
    options.method = method;
    options.chain = chain;
    return fitSkinning(animation, nearestSeedLabels(animation.poses[animation.restPose], bones), options).model;
}

} // namespace trimlab
