// The one skinning fit of `trimlab skin` and the Skinning panel
// (core/skinning/skinning_pipeline.h) on small tubes: a given segmentation becomes the
// bones as given, a count is met by segmenting anew, the fit's weights are convex with at
// most the influences asked (a limit below the segmentation's 4 is not enforced yet; those
// rows are expected to fail), the original and reconstructed poses are the fit's, a tube
// that two rigid parts move is reproduced exactly, corrections never raise the error,
// refused input throws its typed error, and progress and cancel pass through every stage.
#include "core/skinning/skinning_pipeline.h"

#include "core/skinning/skinning_parameters.h"

#include "core/animation/segment_coloring.h"

#include "skinning_fixtures.h"
#include "task_recording.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 8;
constexpr std::size_t kPoses = 5;

// Rings 0-5 and 6-11 of a tube, one label each.
VertexLabeling twoParts()
{
    return tubeSegments(kRings, kSides, 2);
}

// A tube whose two halves each move by their own rigid motions: one bone per half with
// rigid weights reproduces it up to the float rounding of its positions.
MeshAnimation twoPartTube()
{
    return animationOfModel(randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose, tubeRestPose(kRings, kSides),
                                        rigidWeights(twoParts()), kPoses, 7));
}

SkinningBoneSource givenBones(const VertexLabeling& labeling)
{
    SkinningBoneSource source;
    source.segmentation = BoneSegmentation{labeling, std::vector<WheelColor>(labeling.count), {}};
    for (std::uint32_t b = 0; b < labeling.count; ++b)
        source.segmentation->colors[b] = WheelColor{30.0 * b, 0};
    return source;
}

SkinningBoneSource countedBones(std::size_t count)
{
    SkinningBoneSource source;
    source.count = count;
    source.segmenter.threads = 2;
    return source;
}

// "" when every vertex has 1 … `limit` influences of bones < `bones`, positive, summing
// to 1; else the first problem.
QString weightProblem(const SkinningWeights& w, std::size_t vertices, std::size_t bones, std::size_t limit)
{
    if (w.vertices.size() != vertices || w.boneCount != bones)
        return QString("%1 vertices over %2 bones").arg(w.vertices.size()).arg(w.boneCount);
    for (std::size_t v = 0; v < vertices; ++v) {
        const VertexInfluences& in = w.vertices[v];
        if (in.count == 0 || in.count > limit)
            return QString("vertex %1: %2 influences").arg(v).arg(in.count);
        double sum = 0.0;
        for (std::uint32_t k = 0; k < in.count; ++k) {
            if (in.bones[k] >= bones || !(in.weights[k] > 0.0))
                return QString("vertex %1: bone %2, weight %3").arg(v).arg(in.bones[k]).arg(in.weights[k]);
            sum += in.weights[k];
        }
        if (std::abs(sum - 1.0) > 1e-9)
            return QString("vertex %1: weights sum to %2").arg(v).arg(sum);
    }
    return {};
}

// The fit's poses are the animation's and its model's, and its error is theirs.
void checkPoses(const SkinningFit& fit, const MeshAnimation& animation)
{
    QVERIFY(fit.original == animationPositions(animation));
    QVERIFY(fit.approximation == reconstructPoses(fit.result.model));
    QCOMPARE(fit.approximation.size(), animation.poseCount());
    const SkinningError measured = measureSkinningError(fit.original, fit.approximation, animation.restPose);
    QCOMPARE(measured.eRms, fit.result.error.eRms);
    QCOMPARE(measured.maxDistance, fit.result.error.maxDistance);
}

// The stages a run reported, each once, in the order they began.
std::vector<std::string> stagesOf(const MeshAnimation& animation, const SkinningBoneSource& source,
                                  const SkinningPipelineOptions& options)
{
    StageRecorder recorder;
    (void)runSkinningFit(animation, source, options, recorder.control());
    return recorder.stages;
}

bool contains(const std::vector<std::string>& stages, const std::string& stage)
{
    return std::find(stages.begin(), stages.end(), stage) != stages.end();
}

template <class Error>
QString failure(const MeshAnimation& animation, const SkinningBoneSource& source)
{
    try {
        (void)runSkinningFit(animation, source, {});
    } catch (const Error& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

} // namespace

class TestSkinningPipeline : public QObject {
    Q_OBJECT

private slots:
    // A given segmentation is the bones, in its colours; with rigid weights the pose-to-pose
    // fit reproduces the two rigid halves to float rounding.
    void givenSegmentationReproducesARigidTwoPartMotion()
    {
        const MeshAnimation animation = twoPartTube();
        const SkinningBoneSource source = givenBones(twoParts());
        SkinningPipelineOptions options;
        options.fit.weights.borderWidth = 0.0;
        const std::shared_ptr<const SkinningFit> fit = runSkinningFit(animation, source, options);
        QCOMPARE(fit->bones, twoParts());
        QVERIFY(fit->boneColors == source.segmentation->colors);
        QVERIFY(!fit->search.has_value());
        QCOMPARE(fit->segmentationMs, 0.0);
        QCOMPARE(fit->result.model.boneCount(), std::size_t(2));
        const QString problem = weightProblem(fit->result.model.weights, animation.vertexCount(), 2, 1);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        checkPoses(*fit, animation);
        const SkinningError& error = fit->result.error;
        QVERIFY2(error.rmse / error.diagonal < 1e-6, qPrintable(QString::number(error.rmse / error.diagonal)));
        QCOMPARE(error.perPose.size(), kPoses);
    }

    // A count: the animation segmented anew into exactly that many bones, coloured as the
    // Segmentation panel colours a fresh segmentation. The halves are found up to the ring
    // at their border (whose one-rings straddle both motions); the exported fit from rigid
    // weights, with the weight and rest corrections (the command line's default for it),
    // still reproduces the motion to float rounding.
    void countIsMetBySegmentingAnew()
    {
        const MeshAnimation animation = twoPartTube();
        const SkinningBoneSource source = countedBones(2);
        SkinningPipelineOptions options;
        options.fit.fitExported = true;
        options.fit.weightCorrections = true;
        options.fit.vertexCorrections = true;
        options.fit.weights.borderWidth = 0.0;
        const std::shared_ptr<const SkinningFit> fit = runSkinningFit(animation, source, options);
        QCOMPARE(fit->bones.count, 2u);
        QCOMPARE(fit->bones.labels.size(), animation.vertexCount());
        QCOMPARE(std::set<std::uint32_t>(fit->bones.labels.begin(), fit->bones.labels.end()).size(), std::size_t(2));
        const VertexLabeling halves = twoParts();
        std::size_t same = 0;
        for (std::size_t v = 0; v < halves.labels.size(); ++v)
            same += fit->bones.labels[v] == halves.labels[v] ? 1 : 0;
        const std::size_t differ = std::min(same, halves.labels.size() - same); // labels may come swapped
        QVERIFY2(differ <= kSides, qPrintable(QString("%1 vertices off the halves").arg(differ)));
        const AnimationSegmenter segmenter(animation, source.segmenter);
        QVERIFY(fit->boneColors == colorSegments(segmenter.graph(), fit->bones, segmenter.vertexAreas()));
        QVERIFY(fit->search.has_value());
        QVERIFY(fit->search->cleanedCount >= 2);
        QVERIFY(fit->segmentationMs > 0.0);

        QCOMPARE(fit->result.model.boneCount(), std::size_t(2));
        const QString problem = weightProblem(fit->result.model.weights, animation.vertexCount(), 2, 2);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        checkPoses(*fit, animation);
        const SkinningError& error = fit->result.error;
        QVERIFY2(error.rmse / error.diagonal < 1e-6, qPrintable(QString::number(error.rmse / error.diagonal)));
    }

    // The command line's bones: B segments from partitions of B clusters. Its fit choice:
    // the rigid fit maps the rest pose to each pose with both corrections, lbs and dqs keep
    // their chain without them.
    void commandLineBonesAndFitDefaults()
    {
        const SkinningBoneSource bones = segmentedBones(5, 3);
        QVERIFY(!bones.segmentation);
        QCOMPARE(bones.count, std::size_t(5));
        QCOMPARE(std::size_t(bones.segmenter.partition.clusters), std::size_t(5));
        QCOMPARE(bones.segmenter.threads, 3u);
        SkinningFitOptions rigid;
        rigid.chain = SkinningChain::PoseToPose;
        chooseSkinningFit(rigid, SkinningFitKind::Rigid);
        QVERIFY(rigid.fitExported && rigid.chain == SkinningChain::RestToPose);
        QVERIFY(rigid.vertexCorrections && rigid.weightCorrections);
        SkinningFitOptions dqs;
        dqs.chain = SkinningChain::PoseToPose;
        dqs.vertexCorrections = true;
        chooseSkinningFit(dqs, SkinningFitKind::Dqs);
        QVERIFY(!dqs.fitExported && dqs.method == SkinningMethod::Dqs && dqs.chain == SkinningChain::PoseToPose);
        QVERIFY(!dqs.vertexCorrections && !dqs.weightCorrections);
    }

    // The exported fit with its weight block keeps at most the influences asked for, with
    // convex weights, and uses more than the segmentation's 4 where allowed; without
    // reconstruction the approximation is left empty.
    void influencesStayWithinTheLimit_data()
    {
        QTest::addColumn<int>("limit");
        QTest::newRow("1") << 1;
        QTest::newRow("2") << 2;
        QTest::newRow("3") << 3;
        QTest::newRow("4") << 4;
        QTest::newRow("6") << 6;
        QTest::newRow("8") << 8;
    }

    void influencesStayWithinTheLimit()
    {
        QFETCH(int, limit);
        const MeshAnimation animation = bendingTube(16, 8, 6);
        constexpr std::size_t bones = 8;
        SkinningPipelineOptions options;
        options.fit.fitExported = true;
        options.fit.decomposition.maxInfluences = std::size_t(limit);
        options.fit.decomposition.maxIterations = 10;
        options.fit.weightCorrections = true; // the decomposition's weight block
        options.fit.vertexCorrections = true;
        options.reconstruct = false;
        const std::shared_ptr<const SkinningFit> fit = runSkinningFit(animation, countedBones(bones), options);
        QCOMPARE(fit->result.model.boneCount(), bones);
        const QString problem =
            weightProblem(fit->result.model.weights, animation.vertexCount(), bones, std::size_t(limit));
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        std::uint32_t most = 0;
        for (const VertexInfluences& in : fit->result.model.weights.vertices)
            most = std::max(most, in.count);
        if (std::size_t(limit) > kDefaultInfluences)
            QVERIFY(most > kDefaultInfluences);
        else
            QCOMPARE(std::size_t(most), std::size_t(limit)); // the bending tube blends wherever it may
        QVERIFY(fit->approximation.empty());
        QVERIFY(fit->original == animationPositions(animation));
    }

    // On a tube no skinning reproduces, corrections are kept only when they do not raise
    // E_RMS: the result is never worse than the first fit.
    void correctionsNeverRaiseTheError()
    {
        const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
        SkinningPipelineOptions options;
        options.fit.weightCorrections = true;
        options.fit.vertexCorrections = true;
        const std::shared_ptr<const SkinningFit> fit = runSkinningFit(animation, countedBones(3), options);
        QCOMPARE(fit->result.model.boneCount(), std::size_t(3));
        const QString problem =
            weightProblem(fit->result.model.weights, animation.vertexCount(), 3, kDefaultInfluences);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        checkPoses(*fit, animation);
        QVERIFY(fit->result.error.eRms > 0.0);
        QVERIFY(fit->result.error.eRms <= fit->result.uncorrectedError.eRms);
    }

    // Counts the animation cannot be segmented into throw SkinningBonesError with the
    // segmenter's reason; a given segmentation that does not fit throws
    // std::invalid_argument.
    void refusedInputThrowsTypedErrors()
    {
        const MeshAnimation animation = twoPartTube();
        QVERIFY(!failure<SkinningBonesError>(animation, countedBones(0)).isEmpty());
        const QString tooMany = failure<SkinningBonesError>(animation, countedBones(animation.vertexCount() + 1));
        QVERIFY2(tooMany.contains(QString("segments of %1 vertices").arg(animation.vertexCount())),
                 qPrintable(tooMany));
        MeshAnimation still = animation;
        still.poses.resize(1);
        const QString onePose = failure<SkinningBonesError>(still, countedBones(2));
        QVERIFY2(onePose.contains("1 pose"), qPrintable(onePose));

        SkinningBoneSource noColour = givenBones(twoParts());
        noColour.segmentation->colors.pop_back();
        QVERIFY(!failure<std::invalid_argument>(animation, noColour).isEmpty());
        VertexLabeling shortLabels = twoParts();
        shortLabels.labels.pop_back();
        QVERIFY(!failure<std::invalid_argument>(animation, givenBones(shortLabels)).isEmpty());
    }

    // Progress: the segmenter's stages when segmenting anew, then the fit's, and
    // "reconstruction" last.
    void progressNamesEveryStage()
    {
        const MeshAnimation animation = twoPartTube();
        const std::vector<std::string> counted = stagesOf(animation, countedBones(2), {});
        QVERIFY(counted.size() >= 5);
        QCOMPARE(counted[0], std::string("features"));
        QCOMPARE(counted[1], std::string("partitions"));
        QVERIFY(contains(counted, "weights") && contains(counted, "fit"));
        QCOMPARE(counted.back(), std::string("reconstruction"));

        const std::vector<std::string> given = stagesOf(animation, givenBones(twoParts()), {});
        QVERIFY(!contains(given, "features") && !contains(given, "partitions"));
        QVERIFY(contains(given, "fit"));
        QCOMPARE(given.back(), std::string("reconstruction"));
    }

    // A stop request throws OperationCancelled, also while the bones are being segmented
    // (not a SkinningBonesError).
    void stopThrowsOperationCancelled_data()
    {
        QTest::addColumn<QString>("stage");
        QTest::newRow("features") << "features";
        QTest::newRow("partitions") << "partitions";
        QTest::newRow("fit") << "fit";
    }

    void stopThrowsOperationCancelled()
    {
        QFETCH(QString, stage);
        const MeshAnimation animation = twoPartTube();
        StopAtStage stop{stage.toStdString(), {}};
        QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                                 (void)runSkinningFit(animation, countedBones(2), {}, stop.control()));
        QVERIFY(stop.source.stop_requested());
    }
};

QTEST_APPLESS_MAIN(TestSkinningPipeline)
#include "tst_skinning_pipeline.moc"
