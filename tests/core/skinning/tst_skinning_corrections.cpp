// Skin corrections (thesis 4.1.2): rest-pose displacements (eq. 4.12 / 4.16) and convex
// weight corrections (eq. 4.13–4.15) never increase E_RMS, the corrected weights are
// non-negative, sum to 1 and keep ≤ 4 influences, and each correction can be switched.
#include "core/skinning/skinning_corrections.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fitter.h"

#include "skinning_fixtures.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 10, kBones = 3;
constexpr std::size_t kPoses = 6;

const char* name(SkinningMethod m, SkinningChain c)
{
    if (m == SkinningMethod::Lbs)
        return c == SkinningChain::PoseToPose ? "LBS p2p" : "LBS rest";
    return c == SkinningChain::PoseToPose ? "DQS p2p" : "DQS rest";
}

SkinningFitResult fit(const MeshAnimation& a, SkinningMethod m, SkinningChain c, bool weights, bool vertices)
{
    SkinningFitOptions options;
    options.method = m;
    options.chain = c;
    options.weightCorrections = weights;
    options.vertexCorrections = vertices;
    return fitSkinning(a, tubeSegments(kRings, kSides, kBones), options);
}

} // namespace

class TestSkinningCorrections : public QObject {
    Q_OBJECT
private slots:
    void vertexCorrectionsNeverIncreaseError();
    void correctedWeightsAreConvex();
    void pipelineCorrectionsNeverIncreaseError();
    void correctionsAreSwitchable();
};

void TestSkinningCorrections::vertexCorrectionsNeverIncreaseError()
{
    // Without the pipeline's keep-only-if-better guard: eq. 4.12 is an exact least-squares
    // step in e for fixed transforms, so E_RMS cannot rise (and here it falls).
    const MeshAnimation a = bendingTube(kRings, kSides, kPoses);
    const std::vector<PosePositions> poses = animationPositions(a);
    for (SkinningMethod m : {SkinningMethod::Lbs, SkinningMethod::Dqs})
        for (SkinningChain c : {SkinningChain::PoseToPose, SkinningChain::RestToPose}) {
            SkinningModel model = fit(a, m, c, false, false).model;
            const double before = measureSkinningError(poses, reconstructPoses(model)).eRms;
            const std::vector<glm::dvec3> e = restPoseCorrections(model, poses);
            for (std::size_t j = 0; j < e.size(); ++j)
                model.restPositions[j] += e[j];
            const double after = measureSkinningError(poses, reconstructPoses(model)).eRms;
            qInfo("%s: E_RMS %.4f -> %.4f with rest-pose corrections", name(m, c), before, after);
            QVERIFY(after <= before * (1.0 + 1e-12));
            QVERIFY(after < before);
        }
}

void TestSkinningCorrections::correctedWeightsAreConvex()
{
    const MeshAnimation a = bendingTube(kRings, kSides, kPoses);
    const std::vector<PosePositions> poses = animationPositions(a);
    const VertexGraph graph = buildVertexGraph(a.vertexCount(), a.triangles);
    for (SkinningMethod m : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        const SkinningModel model = fit(a, m, SkinningChain::PoseToPose, false, false).model;
        for (bool neighbours : {false, true}) {
            const SkinningWeights w = correctedWeights(model, poses, graph, {neighbours, 2});
            QCOMPARE(w.boneCount, model.boneCount());
            std::size_t changed = 0;
            for (std::size_t j = 0; j < w.vertices.size(); ++j) {
                const VertexInfluences& in = w.vertices[j];
                QVERIFY(in.count >= 1 && in.count <= kMaxInfluences);
                double sum = 0.0;
                for (std::uint32_t i = 0; i < in.count; ++i) {
                    QVERIFY(in.weights[i] >= 0.0);
                    sum += in.weights[i];
                }
                QVERIFY2(std::abs(sum - 1.0) <= 1e-9,
                         qPrintable(QString("vertex %1 sums to %2").arg(j).arg(sum, 0, 'g', 17)));
                changed += in == model.weights.vertices[j] ? 0 : 1;
            }
            requireConvexWeights(w, 1e-9);
            QVERIFY(changed > 0);
        }
    }
}

void TestSkinningCorrections::pipelineCorrectionsNeverIncreaseError()
{
    const MeshAnimation a = bendingTube(kRings, kSides, kPoses);
    for (SkinningMethod m : {SkinningMethod::Lbs, SkinningMethod::Dqs})
        for (SkinningChain c : {SkinningChain::PoseToPose, SkinningChain::RestToPose}) {
            const SkinningFitResult plain = fit(a, m, c, false, false);
            const SkinningFitResult weights = fit(a, m, c, true, false);
            const SkinningFitResult vertices = fit(a, m, c, false, true);
            const SkinningFitResult both = fit(a, m, c, true, true);
            qInfo("%s: E_RMS %.4f, weights %.4f (%s), vertices %.4f, both %.4f", name(m, c), plain.error.eRms,
                  weights.error.eRms, weights.weightCorrectionsKept ? "kept" : "dropped", vertices.error.eRms,
                  both.error.eRms);
            QCOMPARE(weights.uncorrectedError.eRms, plain.error.eRms);
            QVERIFY(weights.error.eRms <= plain.error.eRms);
            QVERIFY(vertices.error.eRms <= plain.error.eRms);
            QVERIFY(both.error.eRms <= plain.error.eRms);
            QVERIFY(vertices.vertexCorrectionsKept);
            requireConvexWeights(both.model.weights, 1e-9);
        }
}

void TestSkinningCorrections::correctionsAreSwitchable()
{
    const MeshAnimation a = bendingTube(kRings, kSides, kPoses);
    const SkinningFitResult plain = fit(a, SkinningMethod::Lbs, SkinningChain::PoseToPose, false, false);
    QVERIFY(!plain.weightCorrectionsKept && !plain.vertexCorrectionsKept);
    QCOMPARE(plain.times.weightCorrectionMs, 0.0);
    QCOMPARE(plain.times.vertexCorrectionMs, 0.0);
    QCOMPARE(plain.model.restPositions, animationPositions(a)[0]);
    const SkinningFitResult vertices = fit(a, SkinningMethod::Lbs, SkinningChain::PoseToPose, false, true);
    QCOMPARE(vertices.model.weights, plain.model.weights); // weights untouched
    QVERIFY(vertices.model.restPositions != plain.model.restPositions);
    QVERIFY(vertices.model.affine == plain.model.affine); // transforms untouched
}

QTEST_APPLESS_MAIN(TestSkinningCorrections)
#include "tst_skinning_corrections.moc"
