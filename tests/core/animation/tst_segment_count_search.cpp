// A segmentation with exactly B segments (segment_count_search.h): every requested count
// from 1 to well past the natural parts is met exactly, the merges join slivers to the part
// they move with (motion_merge.h), and impossible counts are refused.
#include "core/animation/segment_count_search.h"
#include "core/animation/motion_merge.h"
#include "core/animation/segment_sizes.h"

#include "tests/core/skinning/skinning_fixtures.h"

#include <QtTest>

#include <algorithm>
#include <set>

using namespace trimlab;
using namespace trimlab::test;

class TestSegmentCountSearch : public QObject {
    Q_OBJECT
private slots:
    void meetsEveryCount();
    void sliversJoinThePartTheyMoveWith();
    void tinySegmentsMergeFirst();
    void reportsSegmentSizes();
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

void TestSegmentCountSearch::sliversJoinThePartTheyMoveWith()
{
    // Three rigid parts of a tube: rings 0-5, 6-8, 9-11, each moved by its own random
    // rigid motions. Over-segmented into 0-5 | 6 | 7-8 | 9-10 | 11, the sliver at ring 6
    // touches the big first part and its own part: merging by motion puts it with its
    // own part (merging the smallest into the largest neighbour would put it with the
    // big one), and the three parts come back exactly.
    constexpr unsigned rings = 12, sides = 10;
    const auto ringLabels = [&](std::initializer_list<unsigned> firstRings) {
        const std::vector<unsigned> starts(firstRings);
        VertexLabeling l;
        l.count = std::uint32_t(starts.size());
        for (unsigned r = 0; r < rings; ++r)
            for (unsigned s = 0; s < sides; ++s)
                l.labels.push_back(
                    std::uint32_t(std::upper_bound(starts.begin(), starts.end(), r) - starts.begin() - 1));
        return l;
    };
    const VertexLabeling parts = ringLabels({0, 6, 9});
    const MeshAnimation rest = tubeRestPose(rings, sides);
    const MeshAnimation animation =
        animationOfModel(randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose, rest, rigidWeights(parts), 5, 11));
    const VertexGraph graph = buildVertexGraph(animation.vertexCount(), animation.triangles);
    const VertexLabeling over = ringLabels({0, 6, 7, 9, 11});
    QCOMPARE(mergeByMotion(animation, graph, over, 3), parts);
    QCOMPARE(mergeByMotion(animation, graph, over, 5), over); // nothing to merge
    QCOMPARE(mergeByMotion(animation, graph, over, 1).count, 1u);
}

void TestSegmentCountSearch::tinySegmentsMergeFirst()
{
    // One vertex of the first part jitters on its own and is a segment of its own; the
    // second part is split in two halves that move together. Asked for 4 segments, the
    // motion rule alone joins the halves (they cost nothing) and leaves the jittering
    // vertex a segment; with a minimum size of 2 vertices it is merged first.
    constexpr unsigned rings = 12, sides = 10;
    VertexLabeling parts;
    parts.count = 3;
    for (unsigned r = 0; r < rings; ++r)
        for (unsigned s = 0; s < sides; ++s)
            parts.labels.push_back(r < 6 ? 0u : (r < 9 ? 1u : 2u));
    MeshAnimation animation = animationOfModel(randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose,
                                                           tubeRestPose(rings, sides), rigidWeights(parts), 5, 5));
    constexpr std::size_t odd = 2 * sides + 3; // in the first part
    for (std::size_t t = 1; t < animation.poseCount(); ++t)
        animation.poses[t][odd] += glm::vec3(0.05f * float(t), -0.03f * float(t), 0.02f);
    VertexLabeling over = parts;
    over.count = 5;
    over.labels[odd] = 3;
    for (unsigned s = 0; s < sides; ++s)
        over.labels[8 * sides + s] = 4; // ring 8: the second half of part 1
    const VertexGraph graph = buildVertexGraph(animation.vertexCount(), animation.triangles);
    const VertexLabeling plain = mergeByMotion(animation, graph, over, 4);
    const VertexLabeling sized = mergeByMotion(animation, graph, over, 4, 2);
    const auto smallest = [](const VertexLabeling& l) {
        std::vector<std::size_t> sizes(l.count, 0);
        for (std::uint32_t label : l.labels)
            ++sizes[label];
        return *std::min_element(sizes.begin(), sizes.end());
    };
    QCOMPARE(plain.count, 4u);
    QCOMPARE(smallest(plain), std::size_t(1));
    QCOMPARE(sized.count, 4u);
    QVERIFY(smallest(sized) >= 10);
    QCOMPARE(sized.labels[odd], sized.labels[0]); // it went with its own part
}

void TestSegmentCountSearch::reportsSegmentSizes()
{
    VertexLabeling l;
    l.count = 3;
    l.labels.assign(198, 2);
    l.labels.push_back(0);
    l.labels.push_back(1);
    const SegmentSizes sizes = segmentSizes(l);
    QCOMPARE(sizes.sorted, (std::vector<std::size_t>{1, 1, 198}));
    QCOMPARE(sizes.underOnePercent, std::size_t(2)); // 1 of 200 is 0.5 %; 2 of 200 would not be
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
