// Ground truth from a real rig: the libigl elephant (6034 vertices, 24 bones, LBS weights
// and per-frame bone transforms; ../shared/data/SOURCES.md §2). Skinning it gives an
// animation whose exact decomposition is known, so fitting with its weights must give its
// transforms back. A few frames only, to stay fast.
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_pose_fit.h"
#include "core/skinning/skinning_weights.h"

#include "skinning_fixtures.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::test;

namespace {

const std::vector<std::size_t> kFrames = {60, 180, 300, 420};    // far apart: the classical fit
const std::vector<std::size_t> kSequence = {200, 201, 202, 203}; // consecutive: pose to pose

struct RigAnimation {
    ElephantRig rig;
    SkinningWeights weights;          // the rig's weights, ≤ 4 per vertex
    std::vector<PosePositions> poses; // rest pose, then kFrames skinned by LBS
};

RigAnimation skinnedElephant(const std::vector<std::size_t>& frames)
{
    RigAnimation r{loadElephantRig(), {}, {}};
    const std::size_t n = r.rig.mesh.vertexCount(), bones = r.rig.weights.cols;
    std::vector<double> dense(n * bones);
    for (std::size_t v = 0; v < n; ++v)
        for (std::size_t b = 0; b < bones; ++b)
            dense[v * bones + b] = r.rig.weights.at(v, b);
    r.weights = sparseWeightsFromDense(dense, n, bones);
    r.poses.push_back(toDoublePositions(r.rig.mesh.positions));
    for (std::size_t f : frames) {
        PosePositions pose(n);
        for (std::size_t v = 0; v < n; ++v) {
            const VertexInfluences& in = r.weights.vertices[v];
            glm::dvec3 p(0.0);
            for (std::uint32_t i = 0; i < in.count; ++i)
                p += in.weights[i] * r.rig.bone(f, in.bones[i]).apply(r.poses[0][v]);
            pose[v] = p;
        }
        r.poses.push_back(std::move(pose));
    }
    return r;
}

MeshAnimation asAnimation(const RigAnimation& d)
{
    MeshAnimation animation;
    animation.triangles = d.rig.mesh.triangles;
    for (const PosePositions& pose : d.poses)
        animation.poses.emplace_back(pose.begin(), pose.end());
    return animation;
}

} // namespace

class TestSkinningRig : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void rigLayout();
    void fitRecoversRigTransforms();
    void pipelineReproducesRigAnimation();

private:
    std::optional<RigAnimation> m_data;
};

void TestSkinningRig::initTestCase()
{
    if (!std::filesystem::exists(elephantFolder()))
        QSKIP("../shared/data/rigs/libigl-elephant is not available");
    m_data = skinnedElephant(kFrames);
}

void TestSkinningRig::rigLayout()
{
    QCOMPARE(m_data->rig.mesh.vertexCount(), std::size_t(6034));
    QCOMPARE(m_data->rig.weights.rows, std::size_t(6034));
    QCOMPARE(m_data->rig.weights.cols, std::size_t(24));
    QCOMPARE(m_data->rig.animation.rows, std::size_t(288));
    QCOMPARE(m_data->rig.animation.cols, std::size_t(457));
    requireConvexWeights(m_data->weights, 1e-12);
}

void TestSkinningRig::fitRecoversRigTransforms()
{
    const RigAnimation& d = *m_data;
    SkinningModel model = identitySkinningModel(SkinningMethod::Lbs, SkinningChain::RestToPose, d.poses.size(), 0,
                                                d.poses[0], d.weights, d.rig.mesh.triangles);
    fitSkinningTransforms(model, d.poses, {});
    double linear = 0.0, translation = 0.0;
    for (std::size_t i = 0; i < kFrames.size(); ++i)
        for (std::size_t b = 0; b < model.boneCount(); ++b) {
            const Affine3 expected = d.rig.bone(kFrames[i], b);
            const Affine3& got = model.affine[i + 1][b];
            for (int c = 0; c < 3; ++c) {
                for (int r = 0; r < 3; ++r)
                    linear = std::max(linear, std::abs(got.linear[c][r] - expected.linear[c][r]));
                translation = std::max(translation, std::abs(got.translation[c] - expected.translation[c]));
            }
        }
    const SkinningError error = measureSkinningError(d.poses, reconstructPoses(model));
    qInfo("elephant rig: largest linear-part difference %.3g, translation %.3g (diagonal %.1f), relative RMSE %.3g",
          linear, translation, error.diagonal, error.rmse / error.diagonal);
    QVERIFY(linear < 1e-6);
    QVERIFY(translation < 1e-6 * error.diagonal);
    QVERIFY(error.rmse / error.diagonal < 1e-9);
}

void TestSkinningRig::pipelineReproducesRigAnimation()
{
    const RigAnimation& d = *m_data;
    const MeshAnimation animation = asAnimation(d);
    SkinningFitOptions options;
    options.chain = SkinningChain::RestToPose;
    const SkinningFitResult classical = fitSkinning(animation, d.weights, options);
    QVERIFY2(classical.error.rmse / classical.error.diagonal < 1e-6,
             qPrintable(QString("relative RMSE %1").arg(classical.error.rmse / classical.error.diagonal)));
    // The pose-to-pose chain cannot reproduce a rest-to-pose LBS animation exactly (the
    // product of blended matrices is not a blend of products) except for its first step,
    // which is plain LBS. Later steps carry a per-vertex blend of already blended poses,
    // which bones far rotated from the rest pose make visibly non-linear: over frames
    // 200–203 the error grows to ~5e-4 of the diagonal (measured: 0.04, 0.07, 0.09 units).
    const RigAnimation sequence = skinnedElephant(kSequence);
    options.chain = SkinningChain::PoseToPose;
    const SkinningFitResult p2p = fitSkinning(asAnimation(sequence), sequence.weights, options);
    qInfo("elephant rig: E_RMS classical %.3g; pose-to-pose over frames 200-203 %.3g, per pose %.3g %.3g %.3g %.3g "
          "%.3g (thousandths of a unit, diagonal %.1f)",
          classical.error.eRms, p2p.error.eRms, p2p.error.perPose[0], p2p.error.perPose[1], p2p.error.perPose[2],
          p2p.error.perPose[3], p2p.error.perPose[4], p2p.error.diagonal);
    QVERIFY(p2p.error.perPose[1] < 1e-6 * p2p.error.diagonal * 1000.0); // the first step is plain LBS
    QVERIFY(p2p.error.eRmsDiagonal < 1.0);                              // < 0.1 % of the diagonal
}

QTEST_APPLESS_MAIN(TestSkinningRig)
#include "tst_skinning_rig.moc"
