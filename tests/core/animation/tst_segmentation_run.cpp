// The one segmentation run of `trimlab segment` and the Segmentation panel
// (core/animation/segmentation_run.h) on a small bending tube: every vertex is labelled,
// each pose partition has the clusters asked for where the mesh has enough vertices, the
// variable segmentation and its colours are the segmenter's, too few poses are refused with
// SegmentationInputError, a stream completed with completeSegmentation equals the global
// run (the panel's real-time mode), and progress and cancel pass through every stage.
#include "core/animation/segmentation_run.h"

#include "core/animation/segment_coloring.h"

#include "animation_fixtures.h"
#include "task_recording.h"
#include "tests/core/skinning/skinning_fixtures.h"

#include <QtTest>

#include <set>
#include <string>
#include <vector>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 16, kSides = 8;
constexpr std::size_t kPoses = 6, kClusters = 4;

const std::vector<double> kSweep = {0.0, 0.05, 0.2, 0.5, 1.0};

MeshAnimation tube()
{
    return bendingTube(kRings, kSides, kPoses);
}

SegmentationRunOptions optionsFor(FeatureKind kind, ReferenceMode reference = ReferenceMode::Rest)
{
    SegmentationRunOptions options;
    options.settings.feature.kind = kind;
    options.settings.feature.reference = reference;
    options.settings.partition.clusters = kClusters;
    options.settings.threads = 2;
    return options;
}

// "" when `labeling` gives each of `vertices` vertices a label below its count and uses
// every label; else the problem.
QString labelingProblem(const VertexLabeling& labeling, std::size_t vertices)
{
    if (labeling.labels.size() != vertices)
        return QString("%1 labels for %2 vertices").arg(labeling.labels.size()).arg(vertices);
    const std::set<std::uint32_t> used(labeling.labels.begin(), labeling.labels.end());
    if (used.size() != labeling.count || *used.rbegin() >= labeling.count)
        return QString("%1 labels used of %2").arg(used.size()).arg(labeling.count);
    return {};
}

void compareResults(const SegmentationResult& a, const SegmentationResult& b)
{
    const AnimationSegmenter& x = *a.segmenter;
    const AnimationSegmenter& y = *b.segmenter;
    QCOMPARE(x.animation().poses, y.animation().poses);
    QCOMPARE(x.partitionedPoses(), y.partitionedPoses());
    QCOMPARE(x.join().partitionCount(), y.join().partitionCount());
    for (std::size_t i = 0; i < x.join().partitionCount(); ++i)
        QCOMPARE(x.join().partition(i), y.join().partition(i));
    QCOMPARE(x.overSegmentation(), y.overSegmentation());
    for (const double h : kSweep)
        QCOMPARE(x.segment(h), y.segment(h));
    QCOMPARE(a.variable, b.variable);
    QVERIFY(a.variableColors == b.variableColors);
}

// The segmenter of `animation`'s first pose, run, with the other poses appended one at a
// time: the state at the end of a real-time stream.
std::shared_ptr<const AnimationSegmenter> streamed(const MeshAnimation& animation, const SegmenterSettings& settings)
{
    MeshAnimation first = animation;
    first.poses.resize(1);
    auto segmenter = std::make_shared<AnimationSegmenter>(std::move(first), settings);
    segmenter->run();
    for (std::size_t p = 1; p < animation.poseCount(); ++p)
        segmenter->appendPose(animation.poses[p]);
    return segmenter;
}

} // namespace

class TestSegmentationRun : public QObject {
    Q_OBJECT

private slots:
    // Every vertex labelled in every partition, the over-segmentation and each cleaned
    // segmentation; the asked clusters per pose; the variable segmentation and its colours
    // as the segmenter and colorSequence make them.
    void runLabelsEveryVertex()
    {
        const MeshAnimation animation = tube();
        const std::shared_ptr<const SegmentationResult> r =
            runSegmentation(animation, optionsFor(FeatureKind::RotationAngle));
        const AnimationSegmenter& s = *r->segmenter;
        QVERIFY(s.ready());
        QCOMPARE(s.animation().poses, animation.poses);
        QCOMPARE(s.partitionedPoses(), (std::vector<std::size_t>{1, 2, 3, 4, 5}));
        QCOMPARE(s.join().partitionCount(), kPoses - 1);
        const std::size_t vertices = animation.vertexCount();
        for (std::size_t i = 0; i < s.join().partitionCount(); ++i) {
            QCOMPARE(std::size_t(s.join().partition(i).count), kClusters);
            const QString problem = labelingProblem(s.join().partition(i), vertices);
            QVERIFY2(problem.isEmpty(), qPrintable(QString("partition %1: %2").arg(i).arg(problem)));
        }
        QVERIFY(s.overSegmentation().count >= kClusters);
        for (const double h : kSweep) {
            const QString problem = labelingProblem(s.segment(h), vertices);
            QVERIFY2(problem.isEmpty(), qPrintable(QString("h = %1: %2").arg(h).arg(problem)));
        }

        QCOMPARE(r->variable, s.variableSegmentation());
        QCOMPARE(r->variable.size(), s.partitionedPoses().size());
        for (const VertexLabeling& labeling : r->variable) {
            const QString problem = labelingProblem(labeling, vertices);
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
        }
        QVERIFY(r->variableColors == colorSequence(s.graph(), s.vertexAreas(), r->variable));
        for (std::size_t i = 0; i < r->variable.size(); ++i)
            QCOMPARE(r->variableColors[i].size(), std::size_t(r->variable[i].count));

        SegmentationRunOptions plain = optionsFor(FeatureKind::RotationAngle);
        plain.variable = false;
        const std::shared_ptr<const SegmentationResult> without = runSegmentation(animation, plain);
        QVERIFY(without->variable.empty() && without->variableColors.empty());
        QCOMPARE(without->segmenter->overSegmentation(), s.overSegmentation());
    }

    // Each pose partition has the clusters asked for (the tube is connected and has more
    // vertices than any count here); every count gives labels for every vertex.
    void partitionsHaveTheAskedClusters_data()
    {
        QTest::addColumn<int>("clusters");
        QTest::newRow("1") << 1;
        QTest::newRow("3") << 3;
        QTest::newRow("16") << 16;
        QTest::newRow("64") << 64;
    }

    void partitionsHaveTheAskedClusters()
    {
        QFETCH(int, clusters);
        SegmentationRunOptions options = optionsFor(FeatureKind::Velocity);
        options.settings.partition.clusters = std::size_t(clusters);
        options.variable = false;
        const MeshAnimation animation = tube();
        const std::shared_ptr<const SegmentationResult> r = runSegmentation(animation, options);
        const PoseJoin& join = r->segmenter->join();
        QCOMPARE(join.partitionCount(), kPoses - 1);
        for (std::size_t i = 0; i < join.partitionCount(); ++i) {
            QCOMPARE(int(join.partition(i).count), clusters);
            const QString problem = labelingProblem(join.partition(i), animation.vertexCount());
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
        }
        const QString problem = labelingProblem(r->segmenter->segment(0.3), animation.vertexCount());
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // Too few poses for the feature: SegmentationInputError with the poses and what the
    // feature needs; one pose more is enough.
    void tooFewPosesAreRefused_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("poses");
        QTest::addColumn<QString>("message");
        QTest::newRow("rotation") << int(FeatureKind::RotationAngle) << 1
                                  << "the animation has 1 pose; the rotation feature needs at least 2";
        QTest::newRow("velocity") << int(FeatureKind::Velocity) << 1
                                  << "the animation has 1 pose; the velocity feature needs at least 2";
        QTest::newRow("acceleration") << int(FeatureKind::Acceleration) << 2
                                      << "the animation has 2 poses; the acceleration feature needs at least 3";
    }

    void tooFewPosesAreRefused()
    {
        QFETCH(int, kind);
        QFETCH(int, poses);
        QFETCH(QString, message);
        MeshAnimation animation = tube();
        animation.poses.resize(std::size_t(poses));
        const SegmentationRunOptions options = optionsFor(FeatureKind(kind));
        try {
            (void)runSegmentation(animation, options);
            QFAIL("no SegmentationInputError");
        } catch (const SegmentationInputError& e) {
            QCOMPARE(QString(e.what()), message);
        }
        MeshAnimation enough = tube();
        enough.poses.resize(std::size_t(poses) + 1);
        QCOMPARE(runSegmentation(enough, options)->segmenter->partitionedPoses().size(), std::size_t(1));
    }

    // The segmenter's own refusals pass through: no clusters, a malformed animation.
    void badSettingsAreRefused()
    {
        SegmentationRunOptions none = optionsFor(FeatureKind::RotationAngle);
        none.settings.partition.clusters = 0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)runSegmentation(tube(), none));
        MeshAnimation torn = tube();
        torn.poses[2].pop_back();
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 (void)runSegmentation(torn, optionsFor(FeatureKind::RotationAngle)));
    }

    // A stream of poses appended one at a time and completed equals the global run.
    void completedStreamEqualsGlobalRun_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("reference");
        QTest::newRow("rotation, rest") << int(FeatureKind::RotationAngle) << int(ReferenceMode::Rest);
        QTest::newRow("rotation, previous") << int(FeatureKind::RotationAngle) << int(ReferenceMode::Previous);
        QTest::newRow("acceleration") << int(FeatureKind::Acceleration) << int(ReferenceMode::Rest);
    }

    void completedStreamEqualsGlobalRun()
    {
        QFETCH(int, kind);
        QFETCH(int, reference);
        const MeshAnimation animation = tube();
        const SegmentationRunOptions options = optionsFor(FeatureKind(kind), ReferenceMode(reference));
        const std::shared_ptr<const AnimationSegmenter> stream = streamed(animation, options.settings);
        const std::shared_ptr<const SegmentationResult> completed = completeSegmentation(stream);
        QCOMPARE(completed->segmenter.get(), stream.get());
        const std::shared_ptr<const SegmentationResult> global = runSegmentation(animation, options);
        QVERIFY(!global->variable.empty());
        compareResults(*completed, *global);
    }

    // The variable segmentation shown at a pose: the last partitioned pose at or before
    // it, the first before every partitioned pose.
    void variableIndexFollowsThePartitionedPoses()
    {
        const std::shared_ptr<const SegmentationResult> rotation =
            runSegmentation(tube(), optionsFor(FeatureKind::RotationAngle));
        QCOMPARE(rotation->variableIndexAt(0), std::size_t(0)); // the rest pose
        for (std::size_t pose = 1; pose < kPoses; ++pose)
            QCOMPARE(rotation->variableIndexAt(pose), pose - 1);

        const std::shared_ptr<const SegmentationResult> acceleration =
            runSegmentation(tube(), optionsFor(FeatureKind::Acceleration));
        QCOMPARE(acceleration->segmenter->partitionedPoses(), (std::vector<std::size_t>{1, 2, 3, 4}));
        QCOMPARE(acceleration->variableIndexAt(0), std::size_t(0));
        QCOMPARE(acceleration->variableIndexAt(1), std::size_t(0));
        QCOMPARE(acceleration->variableIndexAt(3), std::size_t(2));
        QCOMPARE(acceleration->variableIndexAt(5), std::size_t(3)); // after the last partitioned pose
    }

    void progressNamesEveryStage()
    {
        const MeshAnimation animation = tube();
        StageRecorder full;
        (void)runSegmentation(animation, optionsFor(FeatureKind::RotationAngle), full.control());
        QCOMPARE(full.stages, (std::vector<std::string>{"features", "partitions", "per-pose segments"}));

        SegmentationRunOptions plain = optionsFor(FeatureKind::RotationAngle);
        plain.variable = false;
        StageRecorder fixed;
        (void)runSegmentation(animation, plain, fixed.control());
        QCOMPARE(fixed.stages, (std::vector<std::string>{"features", "partitions"}));

        StageRecorder completing;
        (void)completeSegmentation(streamed(animation, plain.settings), completing.control());
        QCOMPARE(completing.stages, std::vector<std::string>{"per-pose segments"});
    }

    void stopThrowsOperationCancelled_data()
    {
        QTest::addColumn<QString>("stage");
        QTest::newRow("features") << "features";
        QTest::newRow("partitions") << "partitions";
        QTest::newRow("per-pose segments") << "per-pose segments";
    }

    void stopThrowsOperationCancelled()
    {
        QFETCH(QString, stage);
        const MeshAnimation animation = tube();
        const SegmentationRunOptions options = optionsFor(FeatureKind::RotationAngle);
        StopAtStage run{stage.toStdString(), {}};
        QVERIFY_THROWS_EXCEPTION(OperationCancelled, (void)runSegmentation(animation, options, run.control()));
        QVERIFY(run.source.stop_requested());
        if (stage != "per-pose segments")
            return;
        StopAtStage complete{stage.toStdString(), {}};
        QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                                 (void)completeSegmentation(streamed(animation, options.settings), complete.control()));
    }
};

QTEST_APPLESS_MAIN(TestSegmentationRun)
#include "tst_segmentation_run.moc"
