#pragma once
/// \file
/// The per-pixel decision of a dynamic rule (thesis Algorithms 8.11–8.13) as a pure
/// function of one ray's sorted hits through a DynamicFrameScene. The GLSL twin is
/// shaders/common/dynamic_walk.glsl; keep the two identical.
///
/// Conventions (in addition to trim_walk.h, whose span and ordering rules apply):
/// - Each hit has a frame class from its object id (dynamic_frame_scene.h). Reference
///   hits (class 0, 2) move the reference index w_r, current hits (1, 2) the current
///   index w_c; both are counted from the far side at the span start.
/// - The reference class of a point is the reference rule applied there: the static rule
///   of the base mesh for the first set (static(w_r)), and for later sets the reference
///   frame's PartitionCharacterization at the interval index "reference hits behind".
/// - The current class is dynamicInterior(rule, w_r, w_c, reference class) evaluated at
///   the span start and then again just behind every current hit (Algorithm 8.13 line 13):
///   it is constant between consecutive current hits, which is what makes the trim a
///   subset of the current surface.
/// - Trimming on: the shown hit is the first current hit whose two sides classify
///   differently; off: the first current hit. Reference-only hits are never shown.

#include "core/trim/dynamic_rule.h"
#include "core/trim/partition_characterization.h"
#include "core/trim/ray_hit.h"
#include "core/trim/static_rule.h"
#include "core/trim/trim_settings.h"
#include "core/trim/trim_walk.h"

#include <span>

namespace trimlab {

/// Where a walk takes the reference frame's classification from.
struct ReferenceClassification {
    /// nullptr: the reference is the base mesh, classified by `staticRule`.
    const PartitionCharacterization* characterization = nullptr;
    StaticRule staticRule = StaticRule::AlternatingBorder;
};

struct DynamicWalkResult {
    TrimWalk walk;           ///< windingAtStart is the current index w_c at the span start
    bool unresolved = false; ///< the reference characterization overflowed where it was needed
};

/// Walks one ray for display (with the user's clip plane in `span`).
[[nodiscard]] DynamicWalkResult walkDynamicRay(std::span<const RayHit> sortedHits, const KeptSpan& span,
                                               const TrimSettings& settings, DynamicRule rule,
                                               const ReferenceClassification& reference);

/// Characterizes the current frame along the whole ray [zNear, zFar] (no clipping):
/// what the next set uses as its reference (computed once per reference frame and view).
[[nodiscard]] PartitionCharacterization characterizeDynamicRay(std::span<const RayHit> sortedHits, DynamicRule rule,
                                                               const ReferenceClassification& reference);

} // namespace trimlab
