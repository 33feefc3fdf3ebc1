#include "core/trim/temporal_coherence.h"

#include <cmath>
#include <stdexcept>

namespace trimlab {

namespace {

/// The fragment of `after` on the same triangle within the tolerance, or nullptr.
const ClassifiedFragment* sameFragment(const ClassifiedFragment& f, std::span<const ClassifiedFragment> after,
                                       double depthTolerance)
{
    for (const ClassifiedFragment& g : after)
        if (g.triangle == f.triangle && std::abs(g.depth - f.depth) <= depthTolerance)
            return &g;
    return nullptr;
}

} // namespace

PixelCoherence comparePixel(std::span<const ClassifiedFragment> before, std::span<const ClassifiedFragment> after,
                            double depthTolerance)
{
    PixelCoherence result;
    for (const ClassifiedFragment& f : before) {
        const ClassifiedFragment* g = sameFragment(f, after, depthTolerance);
        if (!g)
            continue;
        result.unmoved = true;
        const bool flipped = f.interiorFront != g->interiorFront || f.interiorBack != g->interiorBack;
        const bool swept = f.windingFront != g->windingFront || f.windingBack != g->windingBack;
        result.flipped = result.flipped || flipped;
        result.trimFlipped = result.trimFlipped || f.kept() != g->kept();
        result.unsweptFlipped = result.unsweptFlipped || (flipped && !swept);
    }
    return result;
}

CoherenceCounts compareFrames(const FrameFragments& before, const FrameFragments& after, double depthTolerance)
{
    if (before.width != after.width || before.height != after.height)
        throw std::invalid_argument("the two frames have different sizes");
    CoherenceCounts counts;
    for (std::size_t pixel = 0; pixel < before.pixels.size(); ++pixel) {
        if (before.unresolved[pixel] || after.unresolved[pixel]) {
            ++counts.unresolvedPixels;
            continue;
        }
        ++counts.comparedPixels;
        const PixelCoherence p = comparePixel(before.pixels[pixel], after.pixels[pixel], depthTolerance);
        counts.unmovedPixels += p.unmoved ? 1 : 0;
        counts.flippedPixels += p.flipped ? 1 : 0;
        counts.trimFlippedPixels += p.trimFlipped ? 1 : 0;
        counts.unsweptFlippedPixels += p.unsweptFlipped ? 1 : 0;
    }
    return counts;
}

} // namespace trimlab
