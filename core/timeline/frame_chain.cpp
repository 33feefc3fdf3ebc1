#include "core/timeline/frame_chain.h"

namespace trimlab::timeline {

Scene frameScene(const Timeline& timeline, int f, const glm::dmat4& model, const std::string& name)
{
    Scene scene;
    scene.objects.push_back({name, timeline.meshAt(f), model});
    return scene;
}

DynamicChain frameChain(const Timeline& timeline, int f, StaticRule baseRule, const glm::dmat4& model)
{
    std::vector<std::vector<glm::vec3>> frames;
    std::vector<DynamicRule> rules;
    for (const Timeline::ChainLink& link : timeline.chainTo(f)) {
        frames.push_back(timeline.positionsAt(link.referenceFrame));
        rules.push_back(link.rule);
    }
    frames.push_back(timeline.positionsAt(f));
    return makeDynamicChain(timeline.base().triangles, frames, rules, baseRule, model);
}

Bounds chainBounds(const DynamicChain& chain)
{
    Bounds bounds;
    for (const DynamicChainLevel& level : chain.levels)
        bounds.extend(level.frame.scene.worldBounds());
    return bounds;
}

Bounds historyBounds(const Timeline& history)
{
    Bounds bounds = computeBounds(history.base());
    for (int f = 1; f < history.frameCount(); ++f)
        for (const glm::vec3& p : history.frame(f).after)
            bounds.extend(glm::dvec3(p));
    return bounds;
}

} // namespace trimlab::timeline
