#include "core/trim/classified_fragment.h"

namespace trimlab {

namespace {

ClassifiedFragment fragmentAt(std::uint32_t triangle, double depth)
{
    ClassifiedFragment fragment;
    fragment.triangle = triangle;
    fragment.depth = depth;
    return fragment;
}

/// Fills the windings of `fragments` (front to back) from the far side: behind the last
/// one the index is 0, and crossing a front-facing fragment front to back adds one.
void countWindings(std::vector<ClassifiedFragment>& fragments, const std::vector<int>& facings)
{
    int behind = 0;
    for (std::size_t i = fragments.size(); i-- > 0;) {
        fragments[i].windingBack = behind;
        behind -= facings[i];
        fragments[i].windingFront = behind;
    }
}

} // namespace

std::vector<ClassifiedFragment> staticRayFragments(std::span<const RayHit> sortedHits, StaticRule rule)
{
    std::vector<ClassifiedFragment> fragments;
    std::vector<int> facings;
    for (const RayHit& hit : sortedHits) {
        fragments.push_back(fragmentAt(std::uint32_t(hit.primitiveId), hit.t));
        facings.push_back(hit.facing > 0 ? 1 : -1);
    }
    countWindings(fragments, facings);
    for (ClassifiedFragment& f : fragments) {
        f.interiorFront = isInterior(rule, f.windingFront);
        f.interiorBack = isInterior(rule, f.windingBack);
    }
    return fragments;
}

std::vector<ClassifiedFragment> dynamicRayFragments(std::span<const RayHit> sortedHits, const DynamicFrameScene& frame,
                                                    const PartitionCharacterization& current)
{
    std::vector<ClassifiedFragment> fragments;
    std::vector<int> facings;
    for (const RayHit& hit : sortedHits) {
        if (!inCurrent(frameClassOfObject(hit.objectId)))
            continue;
        const std::uint32_t triangle = frame.meshTriangle[std::size_t(hit.objectId)][std::size_t(hit.primitiveId)];
        fragments.push_back(fragmentAt(triangle, hit.t));
        facings.push_back(hit.facing > 0 ? 1 : -1);
    }
    countWindings(fragments, facings);
    const int m = int(fragments.size());
    for (int i = 0; i < m; ++i) {
        fragments[std::size_t(i)].interiorFront = current.interior(m - i);
        fragments[std::size_t(i)].interiorBack = current.interior(m - i - 1);
    }
    return fragments;
}

} // namespace trimlab
