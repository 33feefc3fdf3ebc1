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
/// Interior inspection (TrimSettings::cap, csg, highlight; thesis 8.1.2 "Capping and CSG
/// Operations", Algorithm 8.14 for n operands) extends the same walk:
/// - Per-object windings: with CSG or collision highlighting the walk also carries
///   w_o(t) for every object o < kMaxCsgOperands, counted from the far side like w.
///   The classification of a point is then the CSG expression on the inside bits
///   isInterior(objectRule(o), w_o) (with an expression) or isInterior(rule, w) (without).
/// - Capping: when the span starts at a clipping plane (span.startPlane >= 0) and the
///   start point classifies interior, the pixel shows that plane's cap at tStart and no
///   hit (capPlane >= 0, shownIndex −1).
/// - Collision: the shown hit of object o lies inside another object q (q != o, q <
///   kMaxCsgOperands, isInterior(objectRule(q), w_q) there) or its own object overlaps
///   itself there (|w_o| > 1 on either side).
/// - Coplanar: the number of hits of the kept span at exactly the shown hit's t.
/// - Transparency (TransparencySettings): walkTrimLayers continues the same walk over every
///   hit of the kept span and reports each with its classification on both sides
///   (the shown hit is the first boundary of that list); core/trim/transparency.h
///   composites them.
/// Without these settings the walk is the static walk above, unchanged.

#include "core/trim/clip_plane.h"
#include "core/trim/csg_expression.h"
#include "core/trim/ray_hit.h"
#include "core/trim/trim_image.h"
#include "core/trim/trim_settings.h"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace trimlab {

/// What the walk decided for one ray, as indices into the sorted hit list.
struct TrimWalk {
    int windingAtStart = 0;
    std::ptrdiff_t shownIndex = -1; ///< index of the shown hit, −1 for an empty pixel or a cap
    std::size_t walkBegin = 0;      ///< first hit with t > tStart
    std::size_t walkEnd = 0;        ///< one past the last hit with t <= tEnd
    int capPlane = -1;              ///< the ClipSet plane whose cap the pixel shows, −1: none
    double capDepth = 0.0;          ///< tStart when capPlane >= 0
    bool collision = false;         ///< the shown hit collides (HighlightSettings::collisions)
    int coplanarCount = 0;          ///< hits at the shown hit's t (HighlightSettings::coplanar)
};

/// Winding index per object (index = object id < kMaxCsgOperands).
using ObjectWindings = std::array<int, kMaxCsgOperands>;

/// Bit o set iff object o classifies interior under settings.objectRule(o) at `windings`.
[[nodiscard]] std::uint32_t objectInsideBits(const TrimSettings& settings, const ObjectWindings& windings);

/// The classification of a point with total winding `winding` and per-object `windings`:
/// the CSG expression on objectInsideBits when settings.csg has one, else
/// isInterior(settings.rule, winding).
[[nodiscard]] bool classifiesInterior(const TrimSettings& settings, int winding, const ObjectWindings& windings);

/// Whether a hit of object `objectId` collides, given the per-object windings at it
/// (the hit's own object: `ownBefore` and `ownAfter` on its two sides).
[[nodiscard]] bool hitCollides(const TrimSettings& settings, const ObjectWindings& windings, int objectId,
                               int ownBefore, int ownAfter);

/// Walks one ray (see the conventions above).
[[nodiscard]] TrimWalk walkTrimRay(std::span<const RayHit> sortedHits, const KeptSpan& span,
                                   const TrimSettings& settings);

/// One hit of the kept span as the walk passes it (transparency).
struct WalkLayer {
    std::size_t index = 0;       ///< into the sorted hits
    bool boundary = false;       ///< its two sides classify differently (every hit with trimming off)
    bool interiorBefore = false; ///< the point in front of it classifies interior (false with trimming off)
};

/// Every hit of `walk`'s kept span (walkBegin .. walkEnd) in walk order, classified as
/// walkTrimRay classifies them (the CSG expression when set, else the rule; per-object
/// windings counted from the far side). `layers` is cleared first. The first boundary is
/// walk.shownIndex when the pixel shows no cap.
void walkTrimLayers(std::span<const RayHit> sortedHits, const TrimWalk& walk, const TrimSettings& settings,
                    std::vector<WalkLayer>& layers);

/// The TrimPixel that `walk` describes: the shown hit's depth (as float), ids and facing,
/// and windingAtStart (also for empty pixels with a non-empty span); for a cap its plane
/// and depth; the collision flag and coplanar count.
[[nodiscard]] TrimPixel trimPixelFromWalk(std::span<const RayHit> sortedHits, const TrimWalk& walk);

/// walkTrimRay followed by trimPixelFromWalk.
[[nodiscard]] TrimPixel resolveTrimPixel(std::span<const RayHit> sortedHits, const KeptSpan& span,
                                         const TrimSettings& settings);

} // namespace trimlab
