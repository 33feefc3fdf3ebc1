// Pose partitioning (multi-source region growing and top-down hierarchical clustering):
// a feature step is split exactly at the step, clusters are connected and as many as
// asked, components get their own clusters, results do not depend on the thread count,
// and long work reports progress and can be cancelled.
#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/hierarchical_partition.h"
#include "core/util/parallel_for.h"
#include "core/animation/region_growing_partition.h"
#include "core/animation/vertex_areas.h"

#include "animation_fixtures.h"
#include "test_paths.h"

#include <QtTest>

#include <atomic>
#include <chrono>
#include <set>
#include <thread>

using namespace trimlab;
using trimlab::test::sharedDataPath;

namespace {

// A 20-column strip whose feature is 0 left of x = 10 and 1 from x = 10 on.
struct StepFixture {
    TriangleMesh mesh = test::stripMesh(20);
    VertexGraph graph = buildVertexGraph(mesh.positions.size(), mesh.triangles);
    std::vector<double> areas = vertexAreas(mesh.positions, mesh.triangles);
    std::vector<double> feature;

    StepFixture()
    {
        for (const glm::vec3& p : mesh.positions)
            feature.push_back(p.x < 10.0f ? 0.0 : 1.0);
    }
};

MeshAnimation walkingCat(std::size_t poses)
{
    MeshAnimation a = loadAnimation(sharedDataPath("anim/walking-cat").string());
    a.poses.resize(poses);
    a.poseNames.resize(poses);
    return a;
}

bool haveWalkingCat()
{
    return std::filesystem::exists(sharedDataPath("anim/walking-cat"));
}

} // namespace

class TestAnimationPartition : public QObject {
    Q_OBJECT
private slots:
    void stepIsSplitAtTheStep_data();
    void stepIsSplitAtTheStep();
    void uniformSeedsAreSpread();
    void componentsGetTheirOwnClusters();
    void constantFeatureCannotBeSplit();
    void clustersAreConnectedAndCounted_data();
    void clustersAreConnectedAndCounted();
    void independentOfThreadCount();
    void progressAndCancel();
    void parallelForStopsAndRethrows();
};

void TestAnimationPartition::stepIsSplitAtTheStep_data()
{
    QTest::addColumn<bool>("hierarchical");
    QTest::newRow("region growing") << false;
    QTest::newRow("hierarchical") << true;
}

void TestAnimationPartition::stepIsSplitAtTheStep()
{
    QFETCH(bool, hierarchical);
    const StepFixture f;
    const FeatureView view{f.feature, 1};
    const VertexLabeling p = hierarchical ? hierarchicalPartition(f.graph, view, f.areas, 2)
                                          : regionGrowingPartition(f.graph, view, f.areas, 2);
    QCOMPARE(p.count, 2u);
    for (std::size_t v = 0; v < f.mesh.positions.size(); ++v)
        QCOMPARE(p.labels[v], f.mesh.positions[v].x < 10.0f ? 0u : 1u);
}

// Farthest-point seeds on a 20-column strip (hop distances): from vertex 0 both right-hand
// corners are 19 hops away (0 → 21 → … → 39 uses the diagonals), and the first maximum,
// bottom-right 19, is the first seed; from 19 the top-left corner 20 is 20 hops away (19
// along a row plus one vertical edge), farther than 0 (19 hops), so it is the second.
void TestAnimationPartition::uniformSeedsAreSpread()
{
    const StepFixture f;
    const std::vector<std::uint32_t> seeds = uniformSeeds(f.graph, 4);
    QCOMPARE(seeds.size(), std::size_t(4));
    QCOMPARE(seeds[0], 19u);
    QCOMPARE(seeds[1], 20u);
    QCOMPARE(std::set<std::uint32_t>(seeds.begin(), seeds.end()).size(), std::size_t(4));
    QCOMPARE(uniformSeeds(f.graph, 100).size(), std::size_t(40)); // never more than #V
}

void TestAnimationPartition::componentsGetTheirOwnClusters()
{
    TriangleMesh two = test::stripMesh(4);
    TriangleMesh other = test::stripMesh(4);
    for (glm::vec3& p : other.positions)
        p.y += 5.0f;
    appendMesh(two, other);
    const VertexGraph graph = buildVertexGraph(two.positions.size(), two.triangles);
    const std::vector<double> areas = vertexAreas(two.positions, two.triangles);
    const std::vector<double> feature(two.positions.size(), 0.25);
    for (const bool hierarchical : {false, true}) {
        const VertexLabeling p = hierarchical ? hierarchicalPartition(graph, {feature, 1}, areas, 1)
                                              : regionGrowingPartition(graph, {feature, 1}, areas, 1);
        QCOMPARE(p.count, 2u);
        QVERIFY(labelsAreConnected(graph, p));
        QCOMPARE(p.labels[0], 0u);
        QCOMPARE(p.labels[8], 1u);
    }
}

void TestAnimationPartition::constantFeatureCannotBeSplit()
{
    const StepFixture f;
    const std::vector<double> constant(f.feature.size(), 1.0);
    QCOMPARE(hierarchicalPartition(f.graph, {constant, 1}, f.areas, 5).count, 1u);
}

void TestAnimationPartition::clustersAreConnectedAndCounted_data()
{
    QTest::addColumn<int>("method");
    QTest::addColumn<int>("kind");
    QTest::newRow("region growing, rotation") << int(PartitionMethod::RegionGrowing) << int(FeatureKind::RotationAngle);
    QTest::newRow("hierarchical, rotation") << int(PartitionMethod::Hierarchical) << int(FeatureKind::RotationAngle);
    QTest::newRow("hierarchical, velocity") << int(PartitionMethod::Hierarchical) << int(FeatureKind::Velocity);
    QTest::newRow("region growing, acceleration")
        << int(PartitionMethod::RegionGrowing) << int(FeatureKind::Acceleration);
}

void TestAnimationPartition::clustersAreConnectedAndCounted()
{
    if (!haveWalkingCat())
        QSKIP("../shared/data/anim/walking-cat is missing");
    QFETCH(int, method);
    QFETCH(int, kind);
    SegmenterSettings settings;
    settings.partition.method = PartitionMethod(method);
    settings.partition.clusters = 8;
    settings.feature.kind = FeatureKind(kind);
    AnimationSegmenter segmenter(walkingCat(8), settings);
    segmenter.run();
    QVERIFY(segmenter.join().partitionCount() >= 6);
    for (std::size_t i = 0; i < segmenter.join().partitionCount(); ++i) {
        const VertexLabeling& p = segmenter.join().partition(i);
        QCOMPARE(p.count, 8u); // the cat is one component with 1297 vertices
        QVERIFY(labelsAreConnected(segmenter.graph(), p));
        QCOMPARE(canonicalLabeling(p.labels), p);
    }
}

void TestAnimationPartition::independentOfThreadCount()
{
    if (!haveWalkingCat())
        QSKIP("../shared/data/anim/walking-cat is missing");
    const MeshAnimation cat = walkingCat(10);
    std::vector<std::vector<VertexLabeling>> results;
    for (const unsigned threads : {1u, 2u, 5u}) {
        SegmenterSettings settings;
        settings.threads = threads;
        settings.partition.method = PartitionMethod::Hierarchical;
        AnimationSegmenter segmenter(cat, settings);
        segmenter.run();
        results.emplace_back();
        for (std::size_t i = 0; i < segmenter.join().partitionCount(); ++i)
            results.back().push_back(segmenter.join().partition(i));
        results.back().push_back(segmenter.segment(0.2));
    }
    QVERIFY(results[0] == results[1]);
    QVERIFY(results[0] == results[2]);
}

void TestAnimationPartition::progressAndCancel()
{
    const TriangleMesh strip = test::stripMesh(30);
    std::vector<std::vector<glm::vec3>> poses;
    for (int i = 1; i <= 6; ++i) {
        poses.push_back(strip.positions);
        for (glm::vec3& p : poses.back())
            p.z = p.x > 15.0f ? 0.1f * float(i) * (p.x - 15.0f) : 0.0f;
    }
    SegmenterSettings settings;
    settings.partition.clusters = 3;
    settings.threads = 2;
    AnimationSegmenter segmenter(test::animationOf(strip, poses), settings);
    std::vector<std::string> stages;
    std::size_t lastDone = 0;
    TaskControl control;
    control.progress = [&](const TaskProgress& p) {
        if (stages.empty() || stages.back() != p.stage)
            stages.emplace_back(p.stage);
        QCOMPARE(p.total, std::size_t(6));
        lastDone = p.done;
    };
    segmenter.run(control);
    QCOMPARE(stages, (std::vector<std::string>{"features", "partitions"}));
    QCOMPARE(lastDone, std::size_t(6));
    // Cancelled before it starts: throws, and the segmenter keeps its previous state.
    const VertexLabeling before = segmenter.segment(0.1);
    std::stop_source stop;
    stop.request_stop();
    TaskControl cancelled;
    cancelled.stop = stop.get_token();
    QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                             segmenter.repartition({PartitionMethod::Hierarchical, 5, 5}, cancelled));
    QCOMPARE(segmenter.settings().partition.clusters, std::size_t(3));
    QCOMPARE(segmenter.segment(0.1), before);
    // Cancelled from the progress callback while running.
    AnimationSegmenter fresh(test::animationOf(strip, poses), settings);
    std::stop_source midway;
    TaskControl stopping;
    stopping.stop = midway.get_token();
    stopping.progress = [&](const TaskProgress& p) {
        if (p.done >= 1)
            midway.request_stop();
    };
    QVERIFY_THROWS_EXCEPTION(OperationCancelled, fresh.run(stopping));
    QVERIFY(!fresh.ready());
}

// The pool under stress: every item runs once; a stop requested from the progress
// callback ends the loop early with OperationCancelled (no hang while items still run);
// the first exception of an item is rethrown.
void TestAnimationPartition::parallelForStopsAndRethrows()
{
    std::vector<std::atomic<int>> runs(500);
    parallelFor(runs.size(), 4, [&](std::size_t i) { ++runs[i]; });
    for (const auto& r : runs)
        QCOMPARE(r.load(), 1);
    for (int trial = 0; trial < 20; ++trial) {
        std::atomic<std::size_t> started{0};
        std::stop_source stop;
        TaskControl control;
        control.stop = stop.get_token();
        control.progress = [&](const TaskProgress& p) {
            if (p.done >= 3)
                stop.request_stop();
        };
        QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                                 parallelFor(
                                     2000, 3,
                                     [&](std::size_t) {
                                         ++started;
                                         std::this_thread::sleep_for(std::chrono::microseconds(200));
                                     },
                                     control, "stress"));
        QVERIFY(started.load() < 2000);
    }
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, parallelFor(100, 3, [](std::size_t i) {
                                 if (i == 17)
                                     throw std::runtime_error("item 17");
                             }));
}

QTEST_GUILESS_MAIN(TestAnimationPartition)
#include "tst_animation_partition.moc"
