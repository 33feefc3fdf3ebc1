// Pose-to-pose and classical skinning fits (thesis 4.1.1, eq. 4.7–4.11) on synthetic
// animations made by known bones and weights: LBS and DQS recover their transforms, the
// pose-to-pose and rest-to-pose representations agree, solvers and thread counts do not
// change the result, E_RMS (eq. 2.7) by hand, weights from a segmentation, cancellation.
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_pose_fit.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/skinning/skinning_weights.h"

#include "skinning_fixtures.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 10, kBones = 3;
constexpr std::size_t kPoses = 6;

double maxDifference(const Affine3& a, const Affine3& b)
{
    double d = 0.0;
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r)
            d = std::max(d, std::abs(a.linear[c][r] - b.linear[c][r]));
        d = std::max(d, std::abs(a.translation[c] - b.translation[c]));
    }
    return d;
}

Affine3 boneTransform(const SkinningModel& m, std::size_t t, std::size_t b)
{
    return m.method == SkinningMethod::Lbs ? m.affine[t][b] : toAffine(m.rigid[t][b]);
}

// Fits a copy of `truth` (identity transforms) to its own poses and checks that every
// bone transform and every position comes back.
void checkRecovery(const SkinningModel& truth, double tolerance)
{
    const std::vector<PosePositions> poses = reconstructPoses(truth);
    SkinningModel fitted = identitySkinningModel(truth.method, truth.chain, truth.poseCount(), truth.restPose,
                                                 truth.restPositions, truth.weights, truth.triangles);
    fitSkinningTransforms(fitted, poses, {});
    double worst = 0.0;
    for (std::size_t t = 0; t < truth.poseCount(); ++t)
        for (std::size_t b = 0; b < truth.boneCount(); ++b)
            worst = std::max(worst, maxDifference(boneTransform(truth, t, b), boneTransform(fitted, t, b)));
    QVERIFY2(worst < tolerance, qPrintable(QString("largest transform difference %1").arg(worst)));
    const SkinningError error = measureSkinningError(poses, reconstructPoses(fitted));
    QVERIFY2(error.rmse / error.diagonal < 1e-9,
             qPrintable(QString("relative RMSE %1").arg(error.rmse / error.diagonal)));
}

// Through the whole pipeline from a float animation: E_RMS relative to the diagonal < 1e-6.
void checkPipeline(const SkinningModel& truth)
{
    const MeshAnimation animation = animationOfModel(truth);
    SkinningFitOptions options;
    options.method = truth.method;
    options.chain = truth.chain;
    const SkinningFitResult r = fitSkinning(animation, truth.weights, options);
    QVERIFY2(r.error.rmse / r.error.diagonal < 1e-6,
             qPrintable(QString("relative RMSE %1").arg(r.error.rmse / r.error.diagonal)));
    QCOMPARE(r.error.perPose.size(), kPoses);
    QCOMPARE(r.error.perVertex.size(), animation.vertexCount());
}

SkinningModel tubeModel(SkinningMethod method, SkinningChain chain, unsigned seed)
{
    const MeshAnimation tube = tubeRestPose(kRings, kSides);
    return randomModel(method, chain, tube, tubeWeights(tube, kRings, kSides, kBones), kPoses, seed);
}

} // namespace

class TestSkinningFit : public QObject {
    Q_OBJECT
private slots:
    void lbsPoseToPoseRecoversTransforms();
    void lbsRestToPoseRecoversTransforms();
    void dqsPoseToPoseRecoversTransforms();
    void dqsRestToPoseRecoversTransforms();
    void restPoseInTheMiddle();
    void poseToPoseEqualsRestToPose();
    void denseAndSparseSolversAgree();
    void threadCountDoesNotChangeResults();
    void errorMetricByHand();
    void weightsFromSegmentation();
    void progressAndCancellation();
};

void TestSkinningFit::lbsPoseToPoseRecoversTransforms()
{
    const SkinningModel truth = tubeModel(SkinningMethod::Lbs, SkinningChain::PoseToPose, 1);
    checkRecovery(truth, 1e-7);
    checkPipeline(truth);
}

void TestSkinningFit::lbsRestToPoseRecoversTransforms()
{
    const SkinningModel truth = tubeModel(SkinningMethod::Lbs, SkinningChain::RestToPose, 2);
    checkRecovery(truth, 1e-7);
    checkPipeline(truth);
}

void TestSkinningFit::dqsPoseToPoseRecoversTransforms()
{
    const SkinningModel truth = tubeModel(SkinningMethod::Dqs, SkinningChain::PoseToPose, 3);
    checkRecovery(truth, 1e-7);
    checkPipeline(truth);
}

void TestSkinningFit::dqsRestToPoseRecoversTransforms()
{
    const SkinningModel truth = tubeModel(SkinningMethod::Dqs, SkinningChain::RestToPose, 4);
    checkRecovery(truth, 1e-7);
    checkPipeline(truth);
}

void TestSkinningFit::restPoseInTheMiddle()
{
    // The chain runs 2 → 3 → 4 → 5 and 2 → 1 → 0.
    SkinningModel truth = tubeModel(SkinningMethod::Lbs, SkinningChain::PoseToPose, 5);
    truth.restPose = 2;
    truth.affine[2] = std::vector<Affine3>(kBones);
    QCOMPARE(chainOrder(kPoses, 2), (std::vector<std::size_t>{2, 3, 4, 5, 1, 0}));
    QCOMPARE(truth.previousPose(1), std::size_t(2));
    QCOMPARE(truth.previousPose(0), std::size_t(1));
    checkRecovery(truth, 1e-7);
}

void TestSkinningFit::poseToPoseEqualsRestToPose()
{
    // Eq. 4.9–4.11: T_j^t·v_j^0 reproduces the pose-to-pose evaluation of eq. 4.7 / 4.8.
    const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        SkinningFitOptions options;
        options.method = method;
        const SkinningFitResult r = fitSkinning(animation, tubeSegments(kRings, kSides, kBones), options);
        const std::vector<PosePositions> p2p = reconstructPoses(r.model);
        std::vector<Affine3> perVertex;
        for (std::size_t t = 0; t < kPoses; ++t) {
            const std::vector<Affine3> transforms = restToPoseTransforms(r.model, t);
            QCOMPARE(reconstructPose(r.model, t), p2p[t]);
            for (std::size_t j = 0; j < animation.vertexCount(); ++j) {
                const glm::dvec3 viaRest = transforms[j].apply(r.model.restPositions[j]);
                QVERIFY(glm::length(viaRest - p2p[t][j]) < 1e-12 * r.error.diagonal);
                vertexRestToPose(r.model, j, perVertex);
                QVERIFY(maxDifference(perVertex[t], transforms[j]) < 1e-13);
            }
        }
    }
}

void TestSkinningFit::denseAndSparseSolversAgree()
{
    const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
    const std::vector<PosePositions> poses = animationPositions(animation);
    const SkinningWeights weights = tubeWeights(animation, kRings, kSides, kBones);
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        std::vector<SkinningModel> models;
        for (LinearSolverKind kind : {LinearSolverKind::Dense, LinearSolverKind::Sparse}) {
            models.push_back(identitySkinningModel(method, SkinningChain::PoseToPose, kPoses, 0, poses[0], weights,
                                                   animation.triangles));
            fitSkinningTransforms(models.back(), poses, {kind, 20, 1});
        }
        for (std::size_t t = 0; t < kPoses; ++t)
            for (std::size_t b = 0; b < kBones; ++b)
                QVERIFY(maxDifference(boneTransform(models[0], t, b), boneTransform(models[1], t, b)) < 1e-8);
    }
}

void TestSkinningFit::threadCountDoesNotChangeResults()
{
    const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        SkinningFitOptions options;
        options.method = method;
        options.weightCorrections = true;
        options.vertexCorrections = true;
        options.threads = 1;
        const SkinningFitResult one = fitSkinning(animation, tubeSegments(kRings, kSides, kBones), options);
        options.threads = 3;
        const SkinningFitResult three = fitSkinning(animation, tubeSegments(kRings, kSides, kBones), options);
        QVERIFY(one.model.affine == three.model.affine);
        QVERIFY(one.model.rigid == three.model.rigid);
        QVERIFY(one.model.weights == three.model.weights);
        QVERIFY(one.model.restPositions == three.model.restPositions);
        QCOMPARE(one.error.eRms, three.error.eRms);
    }
}

void TestSkinningFit::errorMetricByHand()
{
    // n = 2 vertices, k = 2 poses; one vertex of pose 1 is off by (3, 4, 0): ‖A − A′‖_F = 5.
    const std::vector<PosePositions> original = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}}};
    std::vector<PosePositions> approx = original;
    approx[1][1] += glm::dvec3(3, 4, 0);
    const SkinningError e = measureSkinningError(original, approx);
    QCOMPARE(e.frobenius, 5.0);
    QCOMPARE(e.eRms, 1000.0 * 5.0 / std::sqrt(12.0)); // 1000·‖A − A′‖_F / √(3nk)
    QCOMPARE(e.rmse, 5.0 / 2.0);                      // ‖A − A′‖_F / √(nk)
    QCOMPARE(e.diagonal, 1.0);
    QCOMPARE(e.eRmsDiagonal, e.eRms);
    QCOMPARE(e.perPose, (std::vector<double>{0.0, 1000.0 * 5.0 / std::sqrt(6.0)}));
    QCOMPARE(e.perVertex[0], 0.0);
    QVERIFY(std::abs(e.perVertex[1] - 5.0 / std::sqrt(2.0)) < 1e-15);
    QCOMPARE(e.maxDistance, 5.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)measureSkinningError(original, {}));
    // The heat map of one pose: the distances of that pose alone.
    QCOMPARE(poseVertexErrors(original[1], approx[1]), (std::vector<double>{0.0, 5.0}));
    QCOMPARE(poseVertexErrors(original[0], approx[0]), (std::vector<double>{0.0, 0.0}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)poseVertexErrors(original[0], {}));
}

void TestSkinningFit::weightsFromSegmentation()
{
    const MeshAnimation tube = tubeRestPose(kRings, kSides);
    const SkinningWeights w = tubeWeights(tube, kRings, kSides, kBones);
    QCOMPARE(w.boneCount, std::size_t(kBones));
    requireConvexWeights(w, 1e-12);
    const VertexLabeling labels = tubeSegments(kRings, kSides, kBones);
    // Ring 0 lies deep inside bone 0, rings 3 and 4 on the border of bones 0 and 1.
    QCOMPARE(w.vertices[0].bones[0], 0u);
    qInfo("ring 0 keeps %.3f of bone 0, the border ring %.3f / %.3f", w.vertices[0].weights[0],
          w.vertices[3 * kSides].weights[0], w.vertices[3 * kSides].weights[1]);
    QVERIFY(w.vertices[0].weights[0] > 0.85); // the segment is only 4 rings long
    const VertexInfluences& border = w.vertices[3 * kSides];
    QVERIFY(border.count >= 2);
    QVERIFY(border.weights[1] > 0.1);
    for (std::size_t v = 0; v < w.vertices.size(); ++v)
        QCOMPARE(w.vertices[v].bones[0], labels.labels[v]); // a vertex's own segment dominates
    const SkinningWeights rigid = tubeWeights(tube, kRings, kSides, kBones, 0.0);
    QCOMPARE(rigid, rigidWeights(labels));
    VertexLabeling bad = labels;
    bad.labels[0] = kBones;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)segmentationWeights(buildVertexGraph(tube.vertexCount(), tube.triangles),
                                                       toDoublePositions(tube.poses[0]), bad));
}

void TestSkinningFit::progressAndCancellation()
{
    const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
    std::vector<std::string> stages;
    TaskControl control;
    control.progress = [&](const TaskProgress& p) {
        if (stages.empty() || stages.back() != p.stage)
            stages.emplace_back(p.stage);
    };
    SkinningFitOptions options;
    options.weightCorrections = true;
    options.vertexCorrections = true;
    const SkinningFitResult r = fitSkinning(animation, tubeSegments(kRings, kSides, kBones), options, control);
    QVERIFY(std::find(stages.begin(), stages.end(), "weights") != stages.end());
    QVERIFY(std::find(stages.begin(), stages.end(), "fit") != stages.end());
    QVERIFY(std::find(stages.begin(), stages.end(), "weight corrections") != stages.end());
    QVERIFY(std::find(stages.begin(), stages.end(), "vertex corrections") != stages.end());
    QVERIFY(r.times.totalMs >= r.times.fitMs);

    std::stop_source stop;
    TaskControl cancelling;
    cancelling.stop = stop.get_token();
    cancelling.progress = [&](const TaskProgress& p) {
        if (p.stage == "fit" && p.done == 2)
            stop.request_stop();
    };
    QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                             (void)fitSkinning(animation, tubeSegments(kRings, kSides, kBones), options, cancelling));
}

QTEST_APPLESS_MAIN(TestSkinningFit)
#include "tst_skinning_fit.moc"
