#include "core/trim/dynamic_reference_renderer.h"

#include "core/trim/dynamic_walk.h"

#include <algorithm>
#include <stdexcept>

namespace trimlab {

DynamicReferenceRenderer::DynamicReferenceRenderer(const DynamicChain& chain) : m_baseRule(chain.baseRule)
{
    if (chain.levels.empty())
        throw std::invalid_argument("a dynamic chain needs at least one level.");
    for (const DynamicChainLevel& level : chain.levels) {
        m_rules.push_back(level.rule);
        m_levels.push_back(std::make_unique<ReferenceRenderer>(level.frame.scene));
    }
}

// The reference classification level `level` walks with: the base rule for level 0,
// otherwise the characterization level − 1 produces along the same ray (recursively).
PartitionCharacterization DynamicReferenceRenderer::referenceOfLevel(std::size_t level, const PixelRay& ray,
                                                                     double tMin, double tMax,
                                                                     std::vector<RayHit>& hits) const
{
    PartitionCharacterization characterization;
    ReferenceClassification reference{nullptr, m_baseRule};
    for (std::size_t j = 0; j < level; ++j) {
        hits.clear();
        m_levels[j]->bvh().intersectAll(ray, tMin, tMax, hits);
        std::sort(hits.begin(), hits.end(), walkOrder);
        characterization = characterizeDynamicRay(hits, m_rules[j], reference);
        reference.characterization = &characterization;
    }
    return characterization;
}

ReferenceResult DynamicReferenceRenderer::render(const Camera& camera, int width, int height,
                                                 const TrimSettings& settings, unsigned threads) const
{
    const std::size_t last = m_levels.size() - 1;
    const RayWalker walker = [&](int x, int y, std::span<const RayHit> sortedHits, const KeptSpan& span,
                                 bool& unresolved) {
        std::vector<RayHit> scratch;
        const PixelRay ray = pixelRay(camera, width, height, x, y);
        const PartitionCharacterization characterization =
            referenceOfLevel(last, ray, camera.zNear, camera.zFar, scratch);
        const ReferenceClassification reference{last == 0 ? nullptr : &characterization, m_baseRule};
        const DynamicWalkResult result = walkDynamicRay(sortedHits, span, settings, m_rules[last], reference);
        unresolved = result.unresolved;
        return result.walk;
    };
    return m_levels[last]->render(camera, width, height, settings, threads, walker);
}

DynamicWalkResult DynamicReferenceRenderer::walkRay(const PixelRay& ray, double tMin, double tMax,
                                                    std::vector<RayHit>& hits) const
{
    const std::size_t last = m_levels.size() - 1;
    const PartitionCharacterization characterization = referenceOfLevel(last, ray, tMin, tMax, hits);
    hits.clear();
    m_levels[last]->bvh().intersectAll(ray, tMin, tMax, hits);
    std::sort(hits.begin(), hits.end(), walkOrder);
    const ReferenceClassification reference{last == 0 ? nullptr : &characterization, m_baseRule};
    TrimSettings settings;
    const KeptSpan span{false, tMin, tMax, true};
    return walkDynamicRay(hits, span, settings, m_rules[last], reference);
}

} // namespace trimlab
