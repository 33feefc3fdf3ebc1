#include "core/trim/dynamic_reference_sequence.h"

#include "core/trim/dynamic_walk.h"
#include "core/util/parallel_for.h"

#include <algorithm>

namespace trimlab {

DynamicReferenceSequence::DynamicReferenceSequence(const Camera& camera, int width, int height, StaticRule baseRule,
                                                   unsigned threads)
    : m_camera(camera), m_width(width), m_height(height), m_baseRule(baseRule), m_threads(threads)
{
}

ReferenceResult DynamicReferenceSequence::renderNext(const DynamicChainLevel& level, const TrimSettings& settings)
{
    const ReferenceRenderer renderer(level.frame.scene);
    const bool first = m_levels == 0;
    const auto referenceAt = [&](int x, int y) {
        return ReferenceClassification{
            first ? nullptr : &m_carried[std::size_t(y) * std::size_t(m_width) + std::size_t(x)], m_baseRule};
    };
    const RayWalker walker = [&](int x, int y, std::span<const RayHit> sortedHits, const KeptSpan& span,
                                 bool& unresolved) {
        const DynamicWalkResult result = walkDynamicRay(sortedHits, span, settings, level.rule, referenceAt(x, y));
        unresolved = result.unresolved;
        return result.walk;
    };
    ReferenceResult result = renderer.render(m_camera, m_width, m_height, settings, m_threads, walker);

    // The whole ray, unclipped: what the next level reads as its reference.
    std::vector<PartitionCharacterization> next(std::size_t(m_width) * std::size_t(m_height));
    parallelFor(std::size_t(m_height), m_threads, [&](std::size_t row) {
        std::vector<RayHit> hits;
        const int y = int(row);
        for (int x = 0; x < m_width; ++x) {
            hits.clear();
            const PixelRay ray = pixelRay(m_camera, m_width, m_height, x, y);
            renderer.bvh().intersectAll(ray, m_camera.zNear, m_camera.zFar, hits);
            std::sort(hits.begin(), hits.end(), walkOrder);
            next[row * std::size_t(m_width) + std::size_t(x)] =
                characterizeDynamicRay(hits, level.rule, referenceAt(x, y));
        }
    });
    m_carried = std::move(next);
    ++m_levels;
    return result;
}

} // namespace trimlab
