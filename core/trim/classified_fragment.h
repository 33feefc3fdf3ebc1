#pragma once
/// \file
/// The fragments of one pixel ray that belong to the shown frame, each with the
/// inside/outside class of the space on its two sides. A fragment is kept — it lies on
/// the boundary of the trimmed solid and is shown when the solid is cut open there —
/// iff its two sides classify differently (thesis 8.1.2, "Clipping and Trimming"). The
/// temporal-coherence measure (temporal_coherence.h) compares these lists between the
/// frames of an animation.

#include "core/trim/dynamic_frame_scene.h"
#include "core/trim/partition_characterization.h"
#include "core/trim/ray_hit.h"
#include "core/trim/static_rule.h"

#include <cstdint>
#include <span>
#include <vector>

namespace trimlab {

struct ClassifiedFragment {
    std::uint32_t triangle = 0; ///< the mesh triangle (a DynamicFrameScene's original index)
    double depth = 0.0;         ///< the hit's ray parameter t, the view depth
    int windingFront = 0;       ///< the shown frame's winding index just in front (eye side)
    int windingBack = 0;        ///< ... just behind
    bool interiorFront = false; ///< class of the point just in front
    bool interiorBack = false;  ///< class of the point just behind

    [[nodiscard]] bool kept() const { return interiorFront != interiorBack; }
};

/// Every hit of a one-object scene (sorted with walkOrder over the whole ray), front to
/// back, classified by `rule` on the winding index counted from the far side
/// (trim_walk.h); the triangle is the hit's primitive id.
[[nodiscard]] std::vector<ClassifiedFragment> staticRayFragments(std::span<const RayHit> sortedHits, StaticRule rule);

/// The current-frame hits (frame classes "both" and "current only") of a ray through
/// `frame`, front to back, classified by `current`: the characterization
/// characterizeDynamicRay gave for the same sorted hits. Of m current hits, the i-th has
/// the interval with m − i current hits behind it in front and m − i − 1 behind
/// (partition_characterization.h): one class per interval between current hits, as the
/// thesis's walk decides it (Algorithm 8.13, line 13; dynamic_walk.h). Windings count the
/// current hits only.
[[nodiscard]] std::vector<ClassifiedFragment> dynamicRayFragments(std::span<const RayHit> sortedHits,
                                                                  const DynamicFrameScene& frame,
                                                                  const PartitionCharacterization& current);

} // namespace trimlab
