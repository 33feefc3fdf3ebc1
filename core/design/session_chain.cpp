#include "core/design/session_chain.h"

namespace trimlab {

DynamicChain dynamicChainTo(const timeline::Timeline& history, int frame, StaticRule baseRule, const glm::dmat4& model)
{
    std::vector<std::vector<glm::vec3>> frames;
    std::vector<DynamicRule> rules;
    for (const timeline::Timeline::ChainLink& link : history.chainTo(frame)) {
        frames.push_back(history.positionsAt(link.referenceFrame));
        rules.push_back(link.rule);
    }
    frames.push_back(history.positionsAt(frame));
    return makeDynamicChain(history.base().triangles, frames, rules, baseRule, model);
}

DynamicChainLevel dynamicShownLevel(const timeline::Timeline& history, const std::vector<glm::vec3>& reference,
                                    const std::vector<glm::vec3>& current, DynamicRule rule, const glm::dmat4& model)
{
    return {makeDynamicFrameScene(history.base().triangles, reference, current, model), rule};
}

} // namespace trimlab
