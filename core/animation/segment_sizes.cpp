#include "core/animation/segment_sizes.h"

#include <algorithm>

namespace trimlab {

SegmentSizes segmentSizes(const VertexLabeling& labeling)
{
    SegmentSizes result;
    result.sorted.assign(labeling.count, 0);
    for (std::uint32_t label : labeling.labels)
        ++result.sorted[label];
    std::sort(result.sorted.begin(), result.sorted.end());
    const std::size_t n = labeling.labels.size();
    result.underOnePercent = std::size_t(
        std::count_if(result.sorted.begin(), result.sorted.end(), [&](std::size_t s) { return 100 * s < n; }));
    return result;
}

} // namespace trimlab
