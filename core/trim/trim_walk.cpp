#include "trim/trim_walk.h"

namespace trimlab {

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
    int w = walk.windingAtStart;
    for (std::size_t i = walk.walkBegin; i < walk.walkEnd; ++i) {
        const int wAfter = w + (sortedHits[i].facing > 0 ? 1 : -1);
        if (!settings.trimEnabled || isTrimBoundary(settings.rule, w, wAfter)) {
            walk.shownIndex = std::ptrdiff_t(i);
            break;
        }
        w = wAfter;
    }
    return walk;
}

TrimPixel trimPixelFromWalk(std::span<const RayHit> sortedHits, const TrimWalk& walk)
{
    TrimPixel pixel;
    pixel.windingAtStart = walk.windingAtStart;
    if (walk.shownIndex < 0)
        return pixel;
    const RayHit& hit = sortedHits[std::size_t(walk.shownIndex)];
    pixel.viewDepth = static_cast<float>(hit.t);
    pixel.primitiveId = hit.primitiveId;
    pixel.objectId = hit.objectId;
    pixel.facing = static_cast<std::int8_t>(hit.facing);
    return pixel;
}

TrimPixel resolveTrimPixel(std::span<const RayHit> sortedHits, const KeptSpan& span, const TrimSettings& settings)
{
    return trimPixelFromWalk(sortedHits, walkTrimRay(sortedHits, span, settings));
}

} // namespace trimlab
