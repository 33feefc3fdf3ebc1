#include "core/trim/dynamic_chain.h"

#include <stdexcept>

namespace trimlab {

DynamicChain makeDynamicChain(const std::vector<glm::uvec3>& triangles,
                              const std::vector<std::vector<glm::vec3>>& frames, const std::vector<DynamicRule>& rules,
                              StaticRule baseRule, const glm::dmat4& modelMatrix)
{
    if (rules.empty() || frames.size() != rules.size() + 1)
        throw std::invalid_argument("a dynamic chain needs one rule per set and one frame more than rules.");
    DynamicChain chain;
    chain.baseRule = baseRule;
    for (std::size_t j = 0; j < rules.size(); ++j)
        chain.levels.push_back({makeDynamicFrameScene(triangles, frames[j], frames[j + 1], modelMatrix), rules[j]});
    return chain;
}

} // namespace trimlab
