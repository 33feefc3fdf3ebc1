// p2p-cleaning (thesis Algorithm 3.2, reduction rule 3.1–3.4): hand-worked examples with
// their thresholds in h, order independence (Lemma 3.1), h = 0 keeps the
// over-segmentation, monotone reduction in h, and agreement with a plain vertex-level
// re-implementation of the rule on real data.
#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/p2p_cleaning.h"
#include "core/animation/vertex_areas.h"

#include "animation_fixtures.h"
#include "test_paths.h"

#include <QtTest>

#include <numeric>
#include <random>

using namespace trimlab;
using test::columnLabels;

namespace {

// A join of column partitions on a 10-column strip with area 1 per vertex (2 per column).
struct StripJoin {
    std::shared_ptr<const VertexGraph> graph;
    PoseJoin join;
    std::vector<double> areas;

    explicit StripJoin(const std::vector<std::vector<std::uint32_t>>& columnPartitions)
        : graph(std::make_shared<const VertexGraph>(buildVertexGraph(20, test::stripMesh(10).triangles))),
          join(graph),
          areas(20, 1.0)
    {
        for (const auto& columns : columnPartitions)
            join.append(columnLabels(columns));
    }
    [[nodiscard]] VertexLabeling clean(double h) const { return P2pCleaner(join, areas).clean(h); }
};

// The rule applied literally on vertices, pose by pose from the last, with the
// conditions read off the vertices of each pair of neighbouring segments (no segment
// graph, no buckets): the oracle for P2pCleaner.
VertexLabeling plainCleaning(const PoseJoin& join, const std::vector<double>& areas, double h)
{
    const VertexGraph& g = join.graph();
    std::vector<std::uint32_t> current = join.overSegmentation().labels;
    for (std::size_t p = join.partitionCount(); p-- > 0;) {
        const VertexLabeling now = canonicalLabeling(current);
        const std::vector<double> area = labelAreas(now.labels, now.count, areas);
        const std::vector<double> cluster = labelAreas(join.partition(p).labels, join.partition(p).count, areas);
        const std::vector<double> previous = labelAreas(join.level(p).labels, join.level(p).count, areas);
        std::vector<std::uint32_t> target(now.count, UINT32_MAX);
        std::vector<std::uint32_t> someVertex(now.count);
        for (std::uint32_t v = 0; v < g.vertexCount(); ++v) {
            someVertex[now.labels[v]] = v;
            for (const std::uint32_t n : g.neighborsOf(v)) {
                const std::uint32_t a = now.labels[v];
                const std::uint32_t b = now.labels[n];
                const bool split = join.level(p).labels[v] == join.level(p).labels[n] &&
                                   join.level(p + 1).labels[v] != join.level(p + 1).labels[n];
                const std::uint32_t t = target[a];
                if (a != b && split && area[b] > area[a] &&
                    (t == UINT32_MAX || area[b] > area[t] || (area[b] == area[t] && b < t)))
                    target[a] = b;
            }
        }
        std::vector<std::uint32_t> merged(now.count);
        std::iota(merged.begin(), merged.end(), 0u);
        auto root = [&](std::uint32_t s) {
            while (merged[s] != s)
                s = merged[s];
            return s;
        };
        const double slack = 1.0 + 1e-12; // equal sums in different orders (see p2p_cleaning.cpp)
        for (std::uint32_t a = 0; a < now.count; ++a) {
            const std::uint32_t v = someVertex[a];
            if (target[a] != UINT32_MAX && area[a] <= h * cluster[join.partition(p).labels[v]] * slack &&
                area[a] <= h * previous[join.level(p).labels[v]] * slack) {
                const std::uint32_t x = root(a);
                const std::uint32_t y = root(target[a]);
                merged[std::max(x, y)] = std::min(x, y);
            }
        }
        for (std::uint32_t& label : current)
            label = root(now.labels[&label - current.data()]);
    }
    return canonicalLabeling(current);
}

std::unique_ptr<AnimationSegmenter> walkingCatSegmenter(std::size_t poses)
{
    const std::filesystem::path folder = test::sharedDataPath("anim/walking-cat");
    if (!std::filesystem::exists(folder))
        return nullptr;
    MeshAnimation cat = loadAnimation(folder.string());
    cat.poses.resize(poses);
    cat.poseNames.resize(poses);
    auto segmenter = std::make_unique<AnimationSegmenter>(std::move(cat), SegmenterSettings{});
    segmenter->run();
    return segmenter;
}

const std::vector<double> kSweep = {0.0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0};

} // namespace

class TestAnimationCleaning : public QObject {
    Q_OBJECT
private slots:
    void threePoseExample_data();
    void threePoseExample();
    void chainOfAbsorptions_data();
    void chainOfAbsorptions();
    void orderDoesNotMatter();
    void zeroKeepsOverSegmentation();
    void realData();
};

// Continues the over-segmentation test's example: C1 = 0–4 | 5–9, C2 = 0–3 | 4–9,
// C3 = 0–6 | 7–9 give S0 = 0–3 (area 8), S1 = 4 (2), S2 = 5–6 (4), S3 = 7–9 (6).
// Pose 3 separates S2|S3 (both in segment 5–9 of OS(C1, C2), area 10): S2 goes to S3 iff
//   a(S2) = 4 ≤ h·a(C3 cluster 0–6) = 14h and ≤ h·10, i.e. h ≥ 0.4.
// Pose 2 separates S0|S1 (segment 0–4 of OS(C1), area 10): S1 goes to S0 iff
//   2 ≤ h·a(C2 cluster 4–9) = 12h and 2 ≤ 10h, i.e. h ≥ 0.2.
// Pose 1 separates S1|S2. If S1 joined S0 (area 10) and S2 did not (area 4): S2 → S0 iff
//   4 ≤ h·a(C1 cluster 5–9) = 10h, h ≥ 0.4 — but then S2 already joined S3 at pose 3, and
//   the two halves (area 10 each) are equal, so neither absorbs the other.
void TestAnimationCleaning::threePoseExample_data()
{
    QTest::addColumn<double>("h");
    QTest::addColumn<std::vector<std::uint32_t>>("expected");
    const std::vector<std::uint32_t> four = {0, 0, 0, 0, 1, 2, 2, 3, 3, 3};
    const std::vector<std::uint32_t> three = {0, 0, 0, 0, 0, 1, 1, 2, 2, 2};
    const std::vector<std::uint32_t> two = {0, 0, 0, 0, 0, 1, 1, 1, 1, 1};
    QTest::newRow("0") << 0.0 << four;
    QTest::newRow("0.19") << 0.19 << four;
    QTest::newRow("0.2") << 0.2 << three;
    QTest::newRow("0.39") << 0.39 << three;
    QTest::newRow("0.4") << 0.4 << two;
    QTest::newRow("1") << 1.0 << two;
}

void TestAnimationCleaning::threePoseExample()
{
    QFETCH(double, h);
    QFETCH(std::vector<std::uint32_t>, expected);
    const StripJoin strip(
        {{0, 0, 0, 0, 0, 1, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1, 1, 1}, {0, 0, 0, 0, 0, 0, 0, 1, 1, 1}});
    QCOMPARE(strip.clean(h), columnLabels(expected));
}

// Two poses; C2 = {0, 3–8} | {1, 2, 9}: S_C = 0 (2), S_A = 1–2 (4), S_B = 3–8 (12),
// S_D = 9 (2), all separated at pose 2 inside one segment of area 20.
//   S_C → S_A iff 2 ≤ 14h (h ≥ 1/7);  S_A → S_B iff 4 ≤ 6h (h ≥ 2/3);
//   S_D → S_B iff 2 ≤ 6h (h ≥ 1/3).
// At h = 0.8 all three absorptions happen together and S_C ends up in S_B's segment even
// though S_C and S_B share C2's cluster (the thesis's sequential loop would keep S_C when
// it visited S_A first).
void TestAnimationCleaning::chainOfAbsorptions_data()
{
    QTest::addColumn<double>("h");
    QTest::addColumn<std::vector<std::uint32_t>>("expected");
    QTest::newRow("0.1") << 0.1 << std::vector<std::uint32_t>{0, 1, 1, 2, 2, 2, 2, 2, 2, 3};
    QTest::newRow("0.2") << 0.2 << std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1, 1, 1, 1, 2};
    QTest::newRow("0.5") << 0.5 << std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1, 1, 1, 1, 1};
    QTest::newRow("0.8") << 0.8 << std::vector<std::uint32_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
}

void TestAnimationCleaning::chainOfAbsorptions()
{
    QFETCH(double, h);
    QFETCH(std::vector<std::uint32_t>, expected);
    const StripJoin strip({{0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, {0, 1, 1, 0, 0, 0, 0, 0, 0, 1}});
    QCOMPARE(strip.clean(h), columnLabels(expected));
}

// Lemma 3.1: visiting the segments of each pose in any order gives the same result.
void TestAnimationCleaning::orderDoesNotMatter()
{
    const StripJoin strip({{0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, {0, 1, 1, 0, 0, 0, 0, 0, 0, 1}});
    const P2pCleaner small(strip.join, strip.areas);
    std::vector<std::uint32_t> reversed = {3, 2, 1, 0};
    QCOMPARE(small.clean(0.8, reversed), small.clean(0.8));
    const auto segmenter = walkingCatSegmenter(12);
    if (!segmenter)
        QSKIP("../shared/data/anim/walking-cat is missing");
    const P2pCleaner& cleaner = segmenter->cleaner();
    std::vector<std::uint32_t> order(cleaner.overSegmentCount());
    std::iota(order.begin(), order.end(), 0u);
    std::mt19937 random(5);
    for (const double h : {0.02, 0.1, 0.3, 1.0}) {
        const VertexLabeling reference = cleaner.clean(h);
        for (int shuffle = 0; shuffle < 5; ++shuffle) {
            std::shuffle(order.begin(), order.end(), random);
            QCOMPARE(cleaner.clean(h, order), reference);
        }
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)cleaner.clean(0.1, std::vector<std::uint32_t>{0, 0}));
}

void TestAnimationCleaning::zeroKeepsOverSegmentation()
{
    const StripJoin strip({{0, 0, 0, 0, 0, 1, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1, 1, 1}});
    QCOMPARE(strip.clean(0.0), strip.join.overSegmentation());
}

// The walking cat, first 12 frames: h = 0 keeps the over-segmentation, the segment count
// does not grow along kSweep (see tst_animation_segmenter.cpp for why not at every h),
// every segment is connected, and the result equals the plain vertex-level rule.
void TestAnimationCleaning::realData()
{
    const auto segmenter = walkingCatSegmenter(12);
    if (!segmenter)
        QSKIP("../shared/data/anim/walking-cat is missing");
    QCOMPARE(segmenter->segment(0.0), segmenter->overSegmentation());
    std::uint32_t previous = UINT32_MAX;
    for (const double h : kSweep) {
        const VertexLabeling cleaned = segmenter->segment(h);
        QVERIFY2(cleaned.count <= previous,
                 qPrintable(QStringLiteral("h = %1: %2 segments").arg(h).arg(cleaned.count)));
        previous = cleaned.count;
        QVERIFY(labelsAreConnected(segmenter->graph(), cleaned));
        QCOMPARE(cleaned, plainCleaning(segmenter->join(), segmenter->vertexAreas(), h));
    }
    QVERIFY(segmenter->overSegmentation().count > 50); // the example is not trivial
}

QTEST_GUILESS_MAIN(TestAnimationCleaning)
#include "tst_animation_cleaning.moc"
