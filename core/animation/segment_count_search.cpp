#include "core/animation/segment_count_search.h"

#include "core/animation/label_adjacency.h"
#include "core/animation/vertex_areas.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

// Segment-level state of mergeSmallestSegments: areas, neighbour sets, and where each
// original segment went.
struct MergeState {
    std::vector<double> area;
    std::vector<std::set<std::uint32_t>> neighbours;
    std::vector<std::uint32_t> into; // union-find parent
    std::vector<bool> alive;

    std::uint32_t find(std::uint32_t s)
    {
        while (into[s] != s)
            s = into[s] = into[into[s]];
        return s;
    }
};

std::uint32_t smallestAlive(const MergeState& state)
{
    std::uint32_t best = 0;
    bool found = false;
    for (std::uint32_t s = 0; s < state.area.size(); ++s)
        if (state.alive[s] && (!found || state.area[s] < state.area[best])) {
            best = s;
            found = true;
        }
    return best;
}

std::uint32_t largestOf(const MergeState& state, std::uint32_t except, const std::set<std::uint32_t>* among)
{
    std::uint32_t best = except;
    auto consider = [&](std::uint32_t s) {
        if (s != except && state.alive[s] && (best == except || state.area[s] > state.area[best]))
            best = s;
    };
    if (among) {
        for (std::uint32_t s : *among)
            consider(s);
    } else {
        for (std::uint32_t s = 0; s < state.area.size(); ++s)
            consider(s);
    }
    return best;
}

void mergeInto(MergeState& state, std::uint32_t from, std::uint32_t to)
{
    state.area[to] += state.area[from];
    for (std::uint32_t n : state.neighbours[from]) {
        state.neighbours[n].erase(from);
        if (n != to) {
            state.neighbours[n].insert(to);
            state.neighbours[to].insert(n);
        }
    }
    state.neighbours[from].clear();
    state.alive[from] = false;
    state.into[from] = to;
}

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
        throw std::invalid_argument("cannot make " + std::to_string(count) + " segments of " + std::to_string(vertices) +
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

VertexLabeling mergeSmallestSegments(const VertexGraph& graph, std::span<const double> areas,
                                     const VertexLabeling& labeling, std::size_t count)
{
    if (labeling.count <= count)
        return labeling;
    MergeState state;
    state.area = labelAreas(labeling.labels, labeling.count, areas);
    for (const auto& list : labelAdjacency(graph, labeling))
        state.neighbours.emplace_back(list.begin(), list.end());
    state.into.resize(labeling.count);
    std::iota(state.into.begin(), state.into.end(), 0u);
    state.alive.assign(labeling.count, true);
    for (std::size_t alive = labeling.count; alive > count; --alive) {
        const std::uint32_t small = smallestAlive(state);
        std::uint32_t target = largestOf(state, small, &state.neighbours[small]);
        if (target == small)
            target = largestOf(state, small, nullptr);
        mergeInto(state, small, target);
    }
    std::vector<std::uint32_t> labels(labeling.labels.size());
    for (std::size_t v = 0; v < labels.size(); ++v)
        labels[v] = state.find(labeling.labels[v]);
    return canonicalLabeling(labels);
}

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
    HSearch search{segmenter, count, 0.0, {}};
    double lo = 0.0, hi = 1.0;
    search.probe(lo);
    if (search.probe(hi) < count) {
        for (int step = 0; step < 40 && search.best.count != count; ++step) {
            const double mid = 0.5 * (lo + hi);
            (search.probe(mid) >= count ? lo : hi) = mid;
        }
    }
    result.h = search.bestH;
    result.cleanedCount = search.best.count;
    result.segmentation = mergeSmallestSegments(segmenter.graph(), segmenter.vertexAreas(), search.best, count);
    result.merged = result.cleanedCount - count;
    return result;
}

} // namespace trimlab
