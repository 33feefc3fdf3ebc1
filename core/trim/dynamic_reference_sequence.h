#pragma once
/// \file
/// The exact dynamic reference over a history that grows one set at a time — an animation
/// played against its previous pose (thesis 8.1.2, Algorithms 8.11–8.13), as the GPU's
/// DynamicTrimRenderer::appendLevel plays it. For one view it keeps, per pixel, the
/// characterization of the last level given, so the next level costs two ray casts per
/// pixel (the walk and the characterization), where DynamicReferenceRenderer over the
/// whole chain re-characterizes every earlier level along every ray. Same decisions: the
/// walk and the characterization are dynamic_walk.h's, in double precision, without
/// fragment limits.

#include "core/trim/dynamic_chain.h"
#include "core/trim/partition_characterization.h"
#include "core/trim/reference_renderer.h"

#include <cstddef>
#include <vector>

namespace trimlab {

class DynamicReferenceSequence {
public:
    /// The view every level is rendered with (a depth range enclosing every frame), and
    /// the rule classifying the base mesh. `threads` = 0: the hardware concurrency.
    DynamicReferenceSequence(const Camera& camera, int width, int height, StaticRule baseRule, unsigned threads = 0);

    /// Renders `level` as the shown level of the chain made of the levels given so far
    /// plus it (the first: against the base mesh), with `settings` (clip planes and the
    /// like apply to the shown level only, as on the GPU), then characterizes it as the
    /// reference of the next level. Ids refer to the level's DynamicFrameScene objects.
    [[nodiscard]] ReferenceResult renderNext(const DynamicChainLevel& level, const TrimSettings& settings);

    [[nodiscard]] std::size_t levelsSeen() const { return m_levels; }

private:
    Camera m_camera;
    int m_width;
    int m_height;
    StaticRule m_baseRule;
    unsigned m_threads;
    std::size_t m_levels = 0;
    std::vector<PartitionCharacterization> m_carried; ///< per pixel, row-major; empty before the first level
};

} // namespace trimlab
