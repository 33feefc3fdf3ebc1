#pragma once
/// \file
/// The exact CPU reference for the dynamic rules: per pixel, the characterization of
/// every earlier level of the chain from its own rays (characterizeDynamicRay), then the
/// shown level walked with walkDynamicRay — the decision the GPU makes with its bit
/// vectors, in double precision and without fragment limits.

#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_walk.h"
#include "core/trim/partition_characterization.h"
#include "core/trim/reference_renderer.h"

#include <memory>
#include <vector>

namespace trimlab {

class DynamicReferenceRenderer {
public:
    /// Copies what it needs; `chain` may die afterwards. Requires at least one level.
    explicit DynamicReferenceRenderer(const DynamicChain& chain);

    /// Renders the last level of the chain. Ids in the result refer to the objects of the
    /// last level's DynamicFrameScene (as the GPU's do).
    [[nodiscard]] ReferenceResult render(const Camera& camera, int width, int height, const TrimSettings& settings,
                                         unsigned threads = 0) const;

    /// The shown level's dynamic walk along any ray, over hits with tMin <= t <= tMax
    /// (the span starts at tMin, trimming on, no clip); `hits` receives the shown
    /// level's sorted hits the result indexes.
    [[nodiscard]] DynamicWalkResult walkRay(const PixelRay& ray, double tMin, double tMax,
                                            std::vector<RayHit>& hits) const;

private:
    [[nodiscard]] PartitionCharacterization referenceOfLevel(std::size_t level, const PixelRay& ray, double tMin,
                                                             double tMax, std::vector<RayHit>& hits) const;

    StaticRule m_baseRule;
    std::vector<DynamicRule> m_rules;
    std::vector<std::unique_ptr<ReferenceRenderer>> m_levels;
};

} // namespace trimlab
