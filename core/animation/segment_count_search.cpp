#include "core/animation/segment_count_search.h"

#include "core/animation/motion_merge.h"

#include "core/animation/label_adjacency.h"
#include "core/animation/vertex_areas.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

// The cleaned count at h; `best` keeps the largest h whose count is still ≥ count.
struct HSearch {
    const AnimationSegmenter& segmenter;
    std::size_t count;
    double bestH = 0.0;
    VertexLabeling best;

    std::size_t probe(double h)
    {
        VertexLabeling s = segmenter.segment(h);
        const std::size_t n = s.count;
        if (n >= count && (best.labels.empty() || n < best.count || (n == best.count && h > bestH))) {
            bestH = h;
            best = std::move(s);
        }
        return n;
    }
};

void requireSearchable(const AnimationSegmenter& segmenter, std::size_t count)
{
    const std::size_t vertices = segmenter.animation().vertexCount();
    if (count == 0 || count > vertices)
        throw std::invalid_argument("cannot make " + std::to_string(count) + " segments of " +
                                    std::to_string(vertices) +
                                    " vertices: the count must be from 1 to the vertex count");
}

// Step 1: a run whose over-segmentation has at least `count` segments.
void partitionForCount(AnimationSegmenter& segmenter, std::size_t count, const TaskControl& control)
{
    const std::size_t vertices = segmenter.animation().vertexCount();
    PartitionSettings settings = segmenter.settings().partition;
    settings.clusters = count;
    if (!segmenter.ready())
        segmenter.run(control);
    if (segmenter.settings().partition.clusters != count)
        segmenter.repartition(settings, control);
    if (segmenter.partitionedPoses().empty())
        throw std::runtime_error("the animation has " + std::to_string(segmenter.animation().poseCount()) +
                                 " pose(s); segmenting it needs at least 2 (3 for the acceleration feature)");
    while (segmenter.overSegmentation().count < count && settings.clusters < vertices) {
        settings.clusters = std::min(vertices, 2 * settings.clusters);
        segmenter.repartition(settings, control);
    }
    if (segmenter.overSegmentation().count < count)
        throw std::runtime_error("the animation's over-segmentation has only " +
                                 std::to_string(segmenter.overSegmentation().count) + " segments, fewer than " +
                                 std::to_string(count));
}

} // namespace

SegmentCountSearch segmentIntoCount(AnimationSegmenter& segmenter, std::size_t count, const TaskControl& control)
{
    requireSearchable(segmenter, count);
    SegmentCountSearch result;
    if (count == 1) {
        result.segmentation.labels.assign(segmenter.animation().vertexCount(), 0);
        result.segmentation.count = 1;
        result.cleanedCount = 1;
        return result;
    }
    partitionForCount(segmenter, count, control);
    result.clusters = segmenter.settings().partition.clusters;
    result.overSegments = segmenter.overSegmentation().count;
    // Aim at twice the count, then merge by motion: the merges remove the slivers a
    // cleaning strength alone leaves (they join the part they move with), so the bones
    // made from the segments cover parts of the mesh, not a few vertices each.
    const std::size_t target = std::min(result.overSegments, 2 * count);
    HSearch search{segmenter, target, 0.0, {}};
    double lo = 0.0, hi = 1.0;
    search.probe(lo);
    if (search.probe(hi) < target) {
        for (int step = 0; step < 40 && search.best.count != target; ++step) {
            const double mid = 0.5 * (lo + hi);
            (search.probe(mid) >= target ? lo : hi) = mid;
        }
    }
    result.h = search.bestH;
    result.cleanedCount = search.best.count;
    // A segment needs a tenth of the average size: below that it is noise, not a part.
    const std::size_t minVertices = segmenter.animation().vertexCount() / (10 * count);
    result.segmentation = mergeByMotion(segmenter.animation(), segmenter.graph(), search.best, count, minVertices);
    result.merged = result.cleanedCount - result.segmentation.count;
    return result;
}

} // namespace trimlab
