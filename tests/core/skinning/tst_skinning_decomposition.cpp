// The skinning decomposition (it fits what a glTF skin plays): its blocks never raise
// the error, it recovers a rigid skinned animation from segmentation weights, the rest
// pose gets joints of its own at the end, weights stay convex, weak bones are
// re-seeded, the affine variant beats the one-shot fit, the rigid model exports exactly as
// fitted, and bad input or a cancel is reported.

#include "skinning_fixtures.h"

#include "core/animation/vertex_graph.h"
#include "core/skinning/skinning_decomposition.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_gltf.h"

#include <QtTest>

#include <random>
#include <stop_token>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 10, kBones = 3;

// An animation made by rigid LBS (the model the decomposition fits) with smooth weights.
MeshAnimation rigidSkinnedTube(std::size_t poses)
{
    const MeshAnimation rest = tubeRestPose(kRings, kSides);
    SkinningModel model = randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose, rest,
                                      tubeWeights(rest, kRings, kSides, kBones, 3.0), poses, 7);
    SkinningModel lbs = identitySkinningModel(SkinningMethod::Lbs, SkinningChain::RestToPose, poses, 0,
                                              model.restPositions, model.weights, model.triangles);
    for (std::size_t t = 0; t < poses; ++t)
        for (std::size_t b = 0; b < kBones; ++b)
            lbs.affine[t][b] = toAffine(model.rigid[t][b]);
    return animationOfModel(lbs);
}

SkinningDecomposition decompose(const MeshAnimation& a, const SkinningDecompositionOptions& options,
                                const TaskControl& control = {})
{
    const VertexGraph graph = buildVertexGraph(a.vertexCount(), a.triangles);
    const std::vector<PosePositions> poses = animationPositions(a);
    // Rigid (one bone per vertex) weights from the segmentation: the fit must find the blend.
    return decomposeSkinning(poses, 0, poses[0], rigidWeights(tubeSegments(kRings, kSides, kBones)), graph, options,
                             control);
}

bool isRotation(const glm::dmat3& m)
{
    const glm::dmat3 gram = glm::transpose(m) * m;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(gram[c][r] - (r == c ? 1.0 : 0.0)) > 1e-9)
                return false;
    return glm::determinant(m) > 0.0;
}

} // namespace

class TestSkinningDecomposition : public QObject {
    Q_OBJECT
private slots:
    void blocksNeverRaiseTheError();
    void recoversRigidSkinning();
    void restPoseGetsItsOwnJointsAtTheEnd();
    void weakBonesAreReseeded();
    void affineVariantBeatsTheOneShotFit();
    void rigidFitExportsAsFitted();
    void badInputAndCancel();
};

void TestSkinningDecomposition::blocksNeverRaiseTheError()
{
    // Without re-seeding every iteration is three exact block minimisations (or no change).
    SkinningDecompositionOptions options;
    options.reseedIterations = 0;
    options.minRelativeGain = 0.0;
    options.maxIterations = 12;
    for (bool rigid : {true, false}) {
        options.rigidJoints = rigid;
        const SkinningDecomposition d = decompose(bendingTube(kRings, kSides, 6), options);
        QCOMPARE(d.iterations, std::size_t(12));
        QCOMPARE(d.eRmsHistory.size(), std::size_t(13)); // and the last transform block
        QVERIFY(d.eRmsHistory.front() <= d.firstFitERms * (1.0 + 1e-12));
        for (std::size_t i = 1; i < d.eRmsHistory.size(); ++i)
            QVERIFY2(d.eRmsHistory[i] <= d.eRmsHistory[i - 1] * (1.0 + 1e-9),
                     qPrintable(
                         QString("iteration %1: %2 after %3").arg(i).arg(d.eRmsHistory[i]).arg(d.eRmsHistory[i - 1])));
        QVERIFY(d.eRmsHistory.back() < 0.8 * d.firstFitERms);
    }
}

void TestSkinningDecomposition::recoversRigidSkinning()
{
    // Data made by rigid LBS with blended weights; started from hard segment weights, the
    // decomposition finds a model an order of magnitude closer than the first fit.
    const MeshAnimation a = rigidSkinnedTube(8);
    const SkinningDecomposition d = decompose(a, {});
    QVERIFY2(d.eRmsHistory.back() < 0.1 * d.firstFitERms,
             qPrintable(QString("%1 from %2").arg(d.eRmsHistory.back()).arg(d.firstFitERms)));
    const SkinningModel model = decomposedSkinningModel(d, 0, a.triangles);
    const SkinningError error = measureSkinningError(animationPositions(a), reconstructPoses(model));
    QVERIFY(std::abs(error.eRms - d.eRmsHistory.back()) <= 1e-9 * (1.0 + error.eRms));
}

void TestSkinningDecomposition::restPoseGetsItsOwnJointsAtTheEnd()
{
    // During the descent the rest pose's transforms are the identity (the gauge). Once the
    // rest positions have become a bind pose fitted for all poses, the rest pose gets
    // joints of its own, which reproduce it better than the bind pose does.
    const MeshAnimation a = bendingTube(kRings, kSides, 6);
    SkinningDecompositionOptions fixedBind;
    fixedBind.updateRestPositions = false;
    fixedBind.updateWeights = false;
    const SkinningDecomposition fixed = decompose(a, fixedBind);
    for (const Affine3& m : fixed.transforms[0])
        QCOMPARE(m, Affine3{});

    const SkinningDecomposition d = decompose(a, {});
    for (const std::vector<Affine3>& pose : d.transforms)
        for (const Affine3& m : pose)
            QVERIFY(isRotation(m.linear));
    requireConvexWeights(d.weights, 1e-12);
    QVERIFY(std::any_of(d.weights.vertices.begin(), d.weights.vertices.end(),
                        [](const VertexInfluences& in) { return in.count > 1; })); // blends were found
    const SkinningModel model = decomposedSkinningModel(d, 0, a.triangles);
    QVERIFY(restPoseMoves(model));
    const std::vector<PosePositions> original = animationPositions(a);
    const PosePositions restPose = reconstructPose(model, 0);
    QCOMPARE(restPose, reconstructPoses(model)[0]);
    double bindError = 0.0, fittedError = 0.0;
    for (std::size_t j = 0; j < restPose.size(); ++j) {
        bindError += glm::dot(d.restPositions[j] - original[0][j], d.restPositions[j] - original[0][j]);
        fittedError += glm::dot(restPose[j] - original[0][j], restPose[j] - original[0][j]);
    }
    QVERIFY2(fittedError < bindError, qPrintable(QString("%1 vs %2").arg(fittedError).arg(bindError)));
}

void TestSkinningDecomposition::weakBonesAreReseeded()
{
    // Bone 3 holds one vertex of the tube's middle: it is moved to where the error is.
    const MeshAnimation a = bendingTube(kRings, kSides, 6);
    VertexLabeling labels = tubeSegments(kRings, kSides, kBones);
    labels.count = kBones + 1;
    labels.labels[kSides * kRings / 2] = kBones;
    const VertexGraph graph = buildVertexGraph(a.vertexCount(), a.triangles);
    const std::vector<PosePositions> poses = animationPositions(a);
    const SkinningDecomposition d = decomposeSkinning(poses, 0, poses[0], rigidWeights(labels), graph, {});
    QVERIFY(d.reseededBones >= 1);
    double support = 0.0;
    for (const VertexInfluences& in : d.weights.vertices)
        for (std::uint32_t i = 0; i < in.count; ++i)
            support += in.bones[i] == kBones ? in.weights[i] : 0.0;
    QVERIFY2(support > 5.0, qPrintable(QString::number(support)));
}

void TestSkinningDecomposition::affineVariantBeatsTheOneShotFit()
{
    const MeshAnimation a = bendingTube(kRings, kSides, 6);
    SkinningFitOptions options;
    options.method = SkinningMethod::Lbs;
    options.chain = SkinningChain::RestToPose;
    const SkinningFitResult plain = fitSkinning(a, tubeSegments(kRings, kSides, kBones), options);
    options.weightCorrections = options.vertexCorrections = true;
    QVERIFY(usesDecomposition(options));
    const SkinningFitResult iterated = fitSkinning(a, tubeSegments(kRings, kSides, kBones), options);
    QVERIFY(iterated.iterations > 1);
    QVERIFY2(iterated.error.eRms < 0.8 * plain.error.eRms,
             qPrintable(QString("%1 vs %2").arg(iterated.error.eRms).arg(plain.error.eRms)));
}

void TestSkinningDecomposition::rigidFitExportsAsFitted()
{
    const MeshAnimation a = bendingTube(kRings, kSides, 6);
    SkinningFitOptions options;
    options.fitExported = options.weightCorrections = options.vertexCorrections = true;
    const SkinningFitResult fit = fitSkinning(a, tubeSegments(kRings, kSides, kBones), options);
    const std::vector<PosePositions> original = animationPositions(a);
    SkinExportOptions exportOptions;
    exportOptions.target = &original;
    const SkinnedGltf gltf = skinnedGltf(fit.model, 24.0, true, exportOptions);
    QCOMPARE(gltf.report.kind, SkinExportKind::RigidTransforms);
    const SkinningError exported = measureSkinningError(original, gltf.report.positions);
    // Only float rounding (and the export's own refit, which can only help) separate them.
    QVERIFY2(exported.eRms <= fit.error.eRms * 1.001 + 1e-3,
             qPrintable(QString("%1 vs %2").arg(exported.eRms).arg(fit.error.eRms)));
}

void TestSkinningDecomposition::badInputAndCancel()
{
    const MeshAnimation a = bendingTube(kRings, kSides, 4);
    const VertexGraph graph = buildVertexGraph(a.vertexCount(), a.triangles);
    std::vector<PosePositions> poses = animationPositions(a);
    const SkinningWeights weights = rigidWeights(tubeSegments(kRings, kSides, kBones));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)decomposeSkinning(poses, 4, poses[0], weights, graph));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)decomposeSkinning({}, 0, poses[0], weights, graph));
    std::vector<PosePositions> short_ = poses;
    short_[2].pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)decomposeSkinning(short_, 0, poses[0], weights, graph));
    std::stop_source stop;
    TaskControl control;
    control.stop = stop.get_token();
    std::size_t reports = 0;
    control.progress = [&](const TaskProgress& p) {
        QCOMPARE(p.stage, std::string_view("fit"));
        if (++reports == 2)
            stop.request_stop();
    };
    QVERIFY_THROWS_EXCEPTION(OperationCancelled,
                             (void)decomposeSkinning(poses, 0, poses[0], weights, graph, {}, control));
}

QTEST_GUILESS_MAIN(TestSkinningDecomposition)
#include "tst_skinning_decomposition.moc"
