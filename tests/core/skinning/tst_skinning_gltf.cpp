// Exporting skinned approximations as glTF 2.0 (skinning_gltf.h): the Khronos glTF
// Validator reports no errors, TrimLab's own glTF animation loader (LBS of the skin's
// joint matrices, morph targets) reproduces the positions the export reports, a DQS fit of
// rigid data exports exactly, and the rigid approximation of an affine fit is never
// better than the fit.
#include "core/animation/gltf_animation.h"
#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_gltf.h"
#include "core/skinning/skinning_gltf_joints.h"

#include "skinning_fixtures.h"
#include "test_paths.h"

#include <QProcess>
#include "gltf_validation.h"

#include <QtTest>

#include <fstream>
#include <iterator>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 10, kBones = 3;
constexpr std::size_t kPoses = 6;

// The file, loaded back, has the reported positions at the keyframe times t/fps (within
// 1e-5 of the rest pose's bounding-box diagonal: the file holds floats).
void requireReproduced(const std::filesystem::path& file, const ExportedSkin& report, double fps,
                       const std::vector<glm::uvec3>& triangles)
{
    const MeshAnimation loaded = loadGltfAnimation(file);
    QCOMPARE(loaded.poseCount(), report.positions.size());
    QCOMPARE(loaded.triangles, triangles);
    const SkinningError difference = measureSkinningError(report.positions, animationPositions(loaded));
    for (std::size_t t = 0; t < loaded.poseCount(); ++t)
        QVERIFY(std::abs(loaded.poseTimes[t] - double(t) / fps) < 1e-6);
    QVERIFY2(
        difference.maxDistance <= 1e-5 * difference.diagonal,
        qPrintable(QString("largest distance %1, diagonal %2").arg(difference.maxDistance).arg(difference.diagonal)));
}

// Piecewise rigid data: rigid weights (one bone per vertex), random DQS bone motions.
MeshAnimation rigidTube()
{
    const MeshAnimation rest = tubeRestPose(kRings, kSides);
    const SkinningModel truth = randomModel(SkinningMethod::Dqs, SkinningChain::PoseToPose, rest,
                                            rigidWeights(tubeSegments(kRings, kSides, kBones)), kPoses, 7);
    return animationOfModel(truth);
}

SkinningFitResult fit(const MeshAnimation& animation, SkinningMethod method, SkinningChain chain, double borderWidth)
{
    SkinningFitOptions options;
    options.method = method;
    options.chain = chain;
    options.weights.borderWidth = borderWidth;
    return fitSkinning(animation, tubeSegments(kRings, kSides, kBones), options);
}

double maxAbs(const glm::dmat3& m)
{
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            d = std::max(d, std::abs(m[c][r]));
    return d;
}

} // namespace

class TestSkinningGltf : public QObject {
    Q_OBJECT
private slots:
    void rigidDqsFitExportsExactly_data();
    void rigidDqsFitExportsExactly();
    void affineFitExportsItsRigidApproximation_data();
    void affineFitExportsItsRigidApproximation();
    void morphTargetsReproduceTheFit();
    void moreThanFourInfluencesWriteJointsOne();
    void closestRotationIsProper();
    void rigidJointsOfARigidModelAreItsBones();
    void solverSweepsLowerTheError();
    void refusesBadInput();
};

void TestSkinningGltf::rigidDqsFitExportsExactly_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("step");
    QTest::addColumn<int>("chain");
    QTest::newRow("glb, LINEAR, pose-to-pose") << "rigid.glb" << false << int(SkinningChain::PoseToPose);
    QTest::newRow("gltf, STEP, rest-to-pose") << "rigid.gltf" << true << int(SkinningChain::RestToPose);
}

void TestSkinningGltf::rigidDqsFitExportsExactly()
{
    QFETCH(QString, file);
    QFETCH(bool, step);
    QFETCH(int, chain);
    const MeshAnimation animation = rigidTube();
    const SkinningFitResult fitted = fit(animation, SkinningMethod::Dqs, SkinningChain(chain), 0.0);
    const std::vector<PosePositions> original = animationPositions(animation);
    const std::filesystem::path path = outputDir() / file.toStdString();
    SkinExportOptions options;
    options.stepInterpolation = step;
    options.target = &original;
    const ExportedSkin report = exportSkinnedGltf(fitted.model, path, 24.0, options);
    QCOMPARE(report.kind, SkinExportKind::RigidTransforms);
    QCOMPARE(report.joints, std::size_t(kBones));
    test::requireValidGltf(path);
    requireReproduced(path, report, 24.0, animation.triangles);
    // Exact up to the float rounding of the input and of the file: RMS distance < 1e-6 of
    // the diagonal (E_RMS ≈ 0), and no worse than the fit beyond that rounding.
    const SkinningError exported = measureSkinningError(original, report.positions);
    QVERIFY2(exported.rmse < 1e-6 * exported.diagonal,
             qPrintable(QString("exported RMSE %1, diagonal %2").arg(exported.rmse).arg(exported.diagonal)));
    QVERIFY(fitted.error.rmse < 1e-6 * exported.diagonal);
}

void TestSkinningGltf::affineFitExportsItsRigidApproximation_data()
{
    QTest::addColumn<int>("chain");
    QTest::newRow("rest-to-pose") << int(SkinningChain::RestToPose);
    QTest::newRow("pose-to-pose") << int(SkinningChain::PoseToPose);
}

void TestSkinningGltf::affineFitExportsItsRigidApproximation()
{
    QFETCH(int, chain);
    const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
    const SkinningFitResult fitted = fit(animation, SkinningMethod::Lbs, SkinningChain(chain), 2.0);
    const std::vector<PosePositions> original = animationPositions(animation);
    const std::filesystem::path path = outputDir() / "affine.glb";
    SkinExportOptions options;
    options.target = &original;
    const ExportedSkin report = exportSkinnedGltf(fitted.model, path, 10.0, options);
    QCOMPARE(report.kind, SkinExportKind::RigidApproximation);
    test::requireValidGltf(path);
    requireReproduced(path, report, 10.0, animation.triangles);
    const SkinningError exported = measureSkinningError(original, report.positions);
    qInfo("fit E_RMS %.4f, exported E_RMS %.4f", fitted.error.eRms, exported.eRms);
    // For the rest-to-pose fit this is a theorem (rigid joints are affine ones and the fit
    // is the least-squares optimum for these weights); for the pose-to-pose chain the fit
    // is not a global optimum, but a rigid skin still does not beat it on this bending.
    QVERIFY(exported.eRms >= fitted.error.eRms * (1.0 - 1e-9));
    QVERIFY(exported.rmse < 0.01 * exported.diagonal); // still a usable approximation
}

void TestSkinningGltf::morphTargetsReproduceTheFit()
{
    const MeshAnimation animation = bendingTube(kRings, kSides, kPoses);
    const SkinningFitResult fitted = fit(animation, SkinningMethod::Lbs, SkinningChain::PoseToPose, 2.0);
    const std::filesystem::path path = outputDir() / "morph.glb";
    SkinExportOptions options;
    options.morphTargets = true;
    const ExportedSkin report = exportSkinnedGltf(fitted.model, path, 30.0, options);
    QCOMPARE(report.kind, SkinExportKind::MorphTargets);
    QCOMPARE(report.joints, std::size_t(0));
    test::requireValidGltf(path);
    requireReproduced(path, report, 30.0, animation.triangles);
    const SkinningError exported = measureSkinningError(animationPositions(animation), report.positions);
    QVERIFY(std::abs(exported.eRms - fitted.error.eRms) < 1e-3 * fitted.error.eRms + 1e-4);
}

// Up to 8 influences (the skinning decomposition's option): JOINTS_1/WEIGHTS_1 carry the
// influences 5-8, and the glTF loader, which blends every set, plays the fitted model.
void TestSkinningGltf::moreThanFourInfluencesWriteJointsOne()
{
    const MeshAnimation rest = tubeRestPose(kRings, kSides);
    constexpr std::size_t bones = 6;
    SkinningWeights weights;
    weights.boneCount = bones;
    for (std::size_t j = 0; j < rest.vertexCount(); ++j) {
        std::vector<std::pair<std::uint32_t, double>> all;
        for (std::uint32_t b = 0; b < bones; ++b) // every bone, more where the ring is near the bone's
            all.emplace_back(b, 1.0 / (1.0 + std::abs(double(j / kSides) - 2.0 * b)));
        weights.vertices.push_back(sparseInfluences(std::move(all), 0, kMaxInfluences));
    }
    QCOMPARE(weights.vertices.front().count, std::uint32_t(bones));
    SkinningModel model = randomModel(SkinningMethod::Dqs, SkinningChain::RestToPose, rest, weights, kPoses, 3);
    SkinningModel rigidLbs = identitySkinningModel(SkinningMethod::Lbs, SkinningChain::RestToPose, kPoses, 0,
                                                   model.restPositions, weights, model.triangles);
    for (std::size_t t = 0; t < kPoses; ++t)
        for (std::size_t b = 0; b < bones; ++b)
            rigidLbs.affine[t][b] = toAffine(model.rigid[t][b]);
    const std::vector<PosePositions> target = reconstructPoses(rigidLbs);
    const std::filesystem::path path = outputDir() / "eight.glb";
    SkinExportOptions options;
    options.target = &target;
    const ExportedSkin report = exportSkinnedGltf(rigidLbs, path, 24.0, options);
    QCOMPARE(report.kind, SkinExportKind::RigidTransforms);
    requireValidGltf(path);
    requireReproduced(path, report, 24.0, rigidLbs.triangles);
    const SkinningError error = measureSkinningError(target, report.positions);
    QVERIFY2(error.maxDistance <= 1e-5 * error.diagonal, qPrintable(QString::number(error.maxDistance)));
    // The file has the second set.
    const std::string bytes = [&] {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    QVERIFY(bytes.find("\"JOINTS_1\"") != std::string::npos && bytes.find("\"WEIGHTS_1\"") != std::string::npos);
}

void TestSkinningGltf::closestRotationIsProper()
{
    const glm::dmat3 rotation = glm::mat3_cast(glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3))));
    const glm::dmat3 stretch(1.3, 0.1, 0.0, 0.1, 0.8, 0.05, 0.0, 0.05, 1.1); // symmetric positive definite
    QVERIFY(maxAbs(closestRotation(rotation * stretch) - rotation) < 1e-12);
    const glm::dmat3 mirrored = rotation * glm::dmat3(1, 0, 0, 0, 1, 0, 0, 0, -1);
    const glm::dmat3 r = closestRotation(mirrored);
    QVERIFY(std::abs(glm::determinant(r) - 1.0) < 1e-12);
    QVERIFY(maxAbs(glm::transpose(r) * r - glm::dmat3(1.0)) < 1e-12);
}

void TestSkinningGltf::rigidJointsOfARigidModelAreItsBones()
{
    const MeshAnimation rest = tubeRestPose(kRings, kSides);
    const SkinningModel model = randomModel(SkinningMethod::Dqs, SkinningChain::PoseToPose, rest,
                                            rigidWeights(tubeSegments(kRings, kSides, kBones)), kPoses, 3);
    const std::vector<PosePositions> poses = reconstructPoses(model);
    const RigidJointAnimation joints = rigidJointAnimation(model, poses);
    const std::vector<std::vector<Affine3>> bones = boneRestToPose(model);
    for (std::size_t t = 0; t < kPoses; ++t)
        for (std::size_t b = 0; b < kBones; ++b) {
            QVERIFY(maxAbs(glm::mat3_cast(joints.poses[t][b].rotation) - bones[t][b].linear) < 1e-9);
            QVERIFY(glm::length(joints.poses[t][b].translation - bones[t][b].translation) < 1e-9);
        }
    const SkinningError error =
        measureSkinningError(poses, rigidSkinPositions(model.restPositions, model.weights, joints));
    QVERIFY(error.maxDistance < 1e-9);
}

void TestSkinningGltf::solverSweepsLowerTheError()
{
    // Smooth weights: DQS blending differs from glTF's linear blend of rigid joints, so the
    // bones' own motions are only a start; the sweeps must improve on it, and E never grows.
    const MeshAnimation rest = tubeRestPose(kRings, kSides);
    const SkinningModel model = randomModel(SkinningMethod::Dqs, SkinningChain::PoseToPose, rest,
                                            tubeWeights(rest, kRings, kSides, kBones), kPoses, 3);
    const std::vector<PosePositions> poses = reconstructPoses(model);
    const std::vector<std::vector<Affine3>> bones = boneRestToPose(model);
    const RigidJointSolver solver(model.weights, model.restPositions);
    double before = 0.0, after = 0.0;
    for (std::size_t t = 1; t < kPoses; ++t) {
        std::vector<RigidJointPose> start;
        for (const Affine3& bone : bones[t])
            start.push_back({glm::normalize(glm::quat_cast(bone.linear)), bone.translation});
        std::vector<RigidJointPose> joints = start;
        const double translationsOnly = solver.solve(joints, poses[t], 0);
        joints = start;
        const double one = solver.solve(joints, poses[t], 1);
        joints = start;
        const double eight = solver.solve(joints, poses[t], 8);
        QVERIFY(one <= translationsOnly && eight <= one);
        before += translationsOnly;
        after += eight;
    }
    qInfo("squared error: translations only %.3g, after 8 sweeps %.3g", before, after);
    QVERIFY(after < before);
}

void TestSkinningGltf::refusesBadInput()
{
    const MeshAnimation animation = rigidTube();
    const SkinningFitResult fitted = fit(animation, SkinningMethod::Dqs, SkinningChain::PoseToPose, 0.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)skinnedGltf(fitted.model, 0.0, true));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)skinnedGltf(fitted.model, std::nan(""), true));
    std::vector<PosePositions> shortTarget(2);
    SkinExportOptions options;
    options.target = &shortTarget;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)skinnedGltf(fitted.model, 24.0, true, options));
    try {
        (void)exportSkinnedGltf(fitted.model, "/nonexistent/folder/x.glb", 24.0);
        QFAIL("an unwritable path was accepted");
    } catch (const std::runtime_error& e) {
        QVERIFY2(std::string(e.what()).find("/nonexistent/folder/x.glb") != std::string::npos, e.what());
    }
}

QTEST_GUILESS_MAIN(TestSkinningGltf)
#include "tst_skinning_gltf.moc"
