// A segmentation with exactly B segments (segment_count_search.h): every requested count
// from 1 to well past the natural parts is met exactly, the merge rule joins the smallest
// segment into its largest neighbour, and impossible counts are refused.
#include "core/animation/segment_count_search.h"

#include "skinning_fixtures.h"

#include <QtTest>

#include <set>

using namespace trimlab;
using namespace trimlab::test;

namespace {

// A path of `n` vertices 0 − 1 − … − n−1 as degenerate triangles (edges only).
VertexGraph pathGraph(std::size_t n)
{
    std::vector<glm::uvec3> triangles;
    for (std::uint32_t v = 0; v + 1 < n; ++v)
        triangles.emplace_back(v, v + 1, v + 1);
    return buildVertexGraph(n, triangles);
}

} // namespace

class TestSegmentCountSearch : public QObject {
    Q_OBJECT
private slots:
    void meetsEveryCount();
    void mergesSmallestIntoLargestNeighbour();
    void refusesImpossibleCounts();
};

void TestSegmentCountSearch::meetsEveryCount()
{
    const MeshAnimation animation = bendingTube(16, 10, 8);
    SegmenterSettings settings;
    settings.threads = 2;
    for (std::size_t count : {1u, 2u, 3u, 5u, 8u, 12u}) {
        settings.partition.clusters = count;
        AnimationSegmenter segmenter(animation, settings);
        const SegmentCountSearch found = segmentIntoCount(segmenter, count);
        QCOMPARE(std::size_t(found.segmentation.count), count);
        QCOMPARE(found.segmentation.labels.size(), animation.vertexCount());
        const std::set<std::uint32_t> used(found.segmentation.labels.begin(), found.segmentation.labels.end());
        QCOMPARE(used.size(), count); // every label is used
        QVERIFY(found.cleanedCount >= count);
        QCOMPARE(found.merged, found.cleanedCount - count);
        if (count > 1)
            QCOMPARE(found.clusters, segmenter.settings().partition.clusters);
    }
}

void TestSegmentCountSearch::mergesSmallestIntoLargestNeighbour()
{
    // Segments along a path: 0 0 0 | 1 | 2 2 | 3 3 3 3; unit areas.
    const VertexGraph graph = pathGraph(10);
    const VertexLabeling labels{{0, 0, 0, 1, 2, 2, 3, 3, 3, 3}, 4};
    const std::vector<double> areas(10, 1.0);
    // Segment 1 (area 1) joins its larger neighbour 0 (area 3) rather than 2 (area 2).
    QCOMPARE(mergeSmallestSegments(graph, areas, labels, 3), (VertexLabeling{{0, 0, 0, 0, 1, 1, 2, 2, 2, 2}, 3}));
    // Then segment 2 (area 2) has two neighbours of area 4; the tie goes to the smaller label.
    QCOMPARE(mergeSmallestSegments(graph, areas, labels, 2), (VertexLabeling{{0, 0, 0, 0, 0, 0, 1, 1, 1, 1}, 2}));
    // With more area on the right, it joins the right.
    std::vector<double> heavier = areas;
    heavier[9] = 2.0;
    QCOMPARE(mergeSmallestSegments(graph, heavier, labels, 2), (VertexLabeling{{0, 0, 0, 0, 1, 1, 1, 1, 1, 1}, 2}));
    QCOMPARE(mergeSmallestSegments(graph, areas, labels, 1).count, 1u);
    QCOMPARE(mergeSmallestSegments(graph, areas, labels, 7), labels);
}

void TestSegmentCountSearch::refusesImpossibleCounts()
{
    const MeshAnimation animation = bendingTube(4, 4, 3);
    AnimationSegmenter segmenter(animation, {});
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)segmentIntoCount(segmenter, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)segmentIntoCount(segmenter, animation.vertexCount() + 1));
    MeshAnimation single = animation;
    single.poses.resize(1);
    AnimationSegmenter lonely(single, {});
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, (void)segmentIntoCount(lonely, 2));
}

QTEST_GUILESS_MAIN(TestSegmentCountSearch)
#include "tst_segment_count_search.moc"
