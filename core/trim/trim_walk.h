#pragma once
/// \file
/// The per-pixel trim decision of thesis 8.1.2 ("Rendering using Static Rules", Algorithms
/// 8.9 and 8.10 with clipping), as a pure function of one ray's sorted hits. The GLSL
/// resolve pass mirrors walkTrimRay line by line; keep the two identical.
///
/// Conventions:
/// - `sortedHits`: every hit of the pixel ray with zNear <= t <= zFar (hits outside do not
///   exist: OpenGL clips them), sorted with walkOrder (t, then objectId, then primitiveId).
/// - Winding index at the start of the kept span, counted from the far side (valid with
///   the eye inside the solid and for any clip-plane orientation, because the far plane
///   lies beyond the scene): w(tStart) = Σ over hits with t > tStart of (back ? +1 : −1).
///   A hit with t == tStart counts as in front of the span start: it neither contributes
///   to w(tStart) nor can be shown (the GPU's strict `f.z > p.depth` test).
/// - The walk visits the hits with tStart < t <= tEnd in order, carrying w: a front-facing
///   hit enters the solid (wAfter = wBefore + 1), a back-facing one exits (wBefore − 1).
///   With trimming on, the shown hit is the first with isTrimBoundary(rule, wBefore,
///   wAfter); with trimming off, simply the first hit. None: the pixel is empty.
/// - An empty span (everything clipped) has w = 0 and shows nothing.

#include "trim/clip_plane.h"
#include "trim/ray_hit.h"
#include "trim/trim_image.h"
#include "trim/trim_settings.h"

#include <cstddef>
#include <span>

namespace trimlab {

/// What the walk decided for one ray, as indices into the sorted hit list.
struct TrimWalk {
    int windingAtStart = 0;
    std::ptrdiff_t shownIndex = -1; ///< index of the shown hit, −1 for an empty pixel
    std::size_t walkBegin = 0;      ///< first hit with t > tStart
    std::size_t walkEnd = 0;        ///< one past the last hit with t <= tEnd
};

/// Walks one ray (see the conventions above).
[[nodiscard]] TrimWalk walkTrimRay(std::span<const RayHit> sortedHits, const KeptSpan& span,
                                   const TrimSettings& settings);

/// The TrimPixel that `walk` describes: the shown hit's depth (as float), ids and facing,
/// and windingAtStart (also for empty pixels with a non-empty span).
[[nodiscard]] TrimPixel trimPixelFromWalk(std::span<const RayHit> sortedHits, const TrimWalk& walk);

/// walkTrimRay followed by trimPixelFromWalk.
[[nodiscard]] TrimPixel resolveTrimPixel(std::span<const RayHit> sortedHits, const KeptSpan& span,
                                         const TrimSettings& settings);

} // namespace trimlab
