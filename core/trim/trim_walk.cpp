#include "core/trim/trim_walk.h"

#include <algorithm>
#include <cstdlib>

namespace trimlab {

namespace {

// The static walk of thesis Algorithms 8.9/8.10 (the path without inspection settings;
// kept exactly as it was so that its results never change).
void walkStatic(std::span<const RayHit> sortedHits, const TrimSettings& settings, TrimWalk& walk)
{
    int w = walk.windingAtStart;
    for (std::size_t i = walk.walkBegin; i < walk.walkEnd; ++i) {
        const int wAfter = w + (sortedHits[i].facing > 0 ? 1 : -1);
        if (!settings.trimEnabled || isTrimBoundary(settings.rule, w, wAfter)) {
            walk.shownIndex = std::ptrdiff_t(i);
            break;
        }
        w = wAfter;
    }
}

ObjectWindings objectWindingsBehind(std::span<const RayHit> sortedHits, std::size_t begin)
{
    ObjectWindings windings{};
    for (std::size_t i = begin; i < sortedHits.size(); ++i) {
        const int o = sortedHits[i].objectId;
        if (o >= 0 && o < kMaxCsgOperands)
            windings[std::size_t(o)] += sortedHits[i].facing < 0 ? 1 : -1;
    }
    return windings;
}

// The walk with per-object windings, capping and collision flags (trimming is on).
void walkInspected(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimSettings& settings,
                   TrimWalk& walk)
{
    ObjectWindings windings = objectWindingsBehind(sortedHits, walk.walkBegin);
    int w = walk.windingAtStart;
    bool before = classifiesInterior(settings, w, windings);
    if (settings.capping() && span.startPlane >= 0 && before) {
        walk.capPlane = span.startPlane;
        walk.capDepth = span.tStart;
        return;
    }
    for (std::size_t i = walk.walkBegin; i < walk.walkEnd; ++i) {
        const RayHit& hit = sortedHits[i];
        const int step = hit.facing > 0 ? 1 : -1;
        const bool tracked = hit.objectId >= 0 && hit.objectId < kMaxCsgOperands;
        const int ownBefore = tracked ? windings[std::size_t(hit.objectId)] : 0;
        w += step;
        if (tracked)
            windings[std::size_t(hit.objectId)] += step;
        const bool after = classifiesInterior(settings, w, windings);
        if (before != after) {
            walk.shownIndex = std::ptrdiff_t(i);
            walk.collision = settings.highlight.collisions && tracked &&
                             hitCollides(settings, windings, hit.objectId, ownBefore, ownBefore + step);
            return;
        }
        before = after;
    }
}

int coplanarCount(std::span<const RayHit> sortedHits, const TrimWalk& walk)
{
    const double t = sortedHits[std::size_t(walk.shownIndex)].t;
    return int(std::count_if(sortedHits.begin() + std::ptrdiff_t(walk.walkBegin),
                             sortedHits.begin() + std::ptrdiff_t(walk.walkEnd),
                             [t](const RayHit& hit) { return hit.t == t; }));
}

} // namespace

std::uint32_t objectInsideBits(const TrimSettings& settings, const ObjectWindings& windings)
{
    std::uint32_t bits = 0;
    for (int o = 0; o < kMaxCsgOperands; ++o)
        if (isInterior(settings.objectRule(o), windings[std::size_t(o)]))
            bits |= 1u << o;
    return bits;
}

bool classifiesInterior(const TrimSettings& settings, int winding, const ObjectWindings& windings)
{
    if (settings.csg.enabled())
        return evaluateCsg(settings.csg.expression, objectInsideBits(settings, windings));
    return isInterior(settings.rule, winding);
}

bool hitCollides(const TrimSettings& settings, const ObjectWindings& windings, int objectId, int ownBefore,
                 int ownAfter)
{
    if (std::max(std::abs(ownBefore), std::abs(ownAfter)) > 1)
        return true;
    for (int q = 0; q < kMaxCsgOperands; ++q)
        if (q != objectId && isInterior(settings.objectRule(q), windings[std::size_t(q)]))
            return true;
    return false;
}

TrimWalk walkTrimRay(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimSettings& settings)
{
    TrimWalk walk;
    if (span.empty)
        return walk;
    const std::size_t n = sortedHits.size();
    while (walk.walkBegin < n && sortedHits[walk.walkBegin].t <= span.tStart)
        ++walk.walkBegin;
    for (std::size_t i = walk.walkBegin; i < n; ++i)
        walk.windingAtStart += sortedHits[i].facing < 0 ? 1 : -1;
    walk.walkEnd = walk.walkBegin;
    while (walk.walkEnd < n && sortedHits[walk.walkEnd].t <= span.tEnd)
        ++walk.walkEnd;
    if (settings.perObjectWinding() || settings.capping())
        walkInspected(sortedHits, span, settings, walk);
    else
        walkStatic(sortedHits, settings, walk);
    if (walk.shownIndex >= 0 && settings.highlight.coplanar)
        walk.coplanarCount = coplanarCount(sortedHits, walk);
    return walk;
}

void walkTrimLayers(std::span<const RayHit> sortedHits, const TrimWalk& walk, const TrimSettings& settings,
                    std::vector<WalkLayer>& layers)
{
    layers.clear();
    ObjectWindings windings{};
    if (settings.perObjectWinding())
        windings = objectWindingsBehind(sortedHits, walk.walkBegin);
    int w = walk.windingAtStart;
    bool before = settings.trimEnabled && classifiesInterior(settings, w, windings);
    for (std::size_t i = walk.walkBegin; i < walk.walkEnd; ++i) {
        const RayHit& hit = sortedHits[i];
        const int step = hit.facing > 0 ? 1 : -1;
        w += step;
        if (hit.objectId >= 0 && hit.objectId < kMaxCsgOperands)
            windings[std::size_t(hit.objectId)] += step;
        const bool after = settings.trimEnabled && classifiesInterior(settings, w, windings);
        layers.push_back({i, !settings.trimEnabled || before != after, before});
        before = after;
    }
}

TrimPixel trimPixelFromWalk(std::span<const RayHit> sortedHits, const TrimWalk& walk)
{
    TrimPixel pixel;
    pixel.windingAtStart = walk.windingAtStart;
    if (walk.capPlane >= 0) {
        pixel.capPlane = static_cast<std::int8_t>(walk.capPlane);
        pixel.viewDepth = static_cast<float>(walk.capDepth);
        return pixel;
    }
    if (walk.shownIndex < 0)
        return pixel;
    const RayHit& hit = sortedHits[std::size_t(walk.shownIndex)];
    pixel.viewDepth = static_cast<float>(hit.t);
    pixel.primitiveId = hit.primitiveId;
    pixel.objectId = hit.objectId;
    pixel.facing = static_cast<std::int8_t>(hit.facing);
    pixel.collision = walk.collision;
    pixel.coplanarCount = static_cast<std::uint8_t>(std::min(walk.coplanarCount, 255));
    return pixel;
}

TrimPixel resolveTrimPixel(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimSettings& settings)
{
    return trimPixelFromWalk(sortedHits, walkTrimRay(sortedHits, span, settings));
}

} // namespace trimlab
