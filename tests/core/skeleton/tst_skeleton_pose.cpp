// Posing a rig (forward kinematics over the parents-first bones) and skinning the rest
// mesh with LBS and DQS (core/skeleton/skeleton_pose.h; thesis 2.3.2–2.3.3). Expected
// positions come from closed formulas, not from the code under test.
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/rig_motion_fit.h"
#include "core/skeleton/skeleton_pose.h"
#include "core/skeleton/skeleton_pose_edit.h"

#include "core/scene/shape_generators.h"

#include "skeleton_rig_fixtures.h"
#include "skeleton_shapes.h"

#include <QElapsedTimer>
#include <QtTest>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

using namespace trimlab;

namespace {

const glm::dquat kQuarterTurnZ = glm::angleAxis(M_PI / 2.0, glm::dvec3(0.0, 0.0, 1.0));

float weightOf(const BoneWeights& w, std::size_t v, int bone)
{
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (w.bones[v][k] == bone)
            return w.weights[v][k];
    return 0.0f;
}

double medianMs(const std::function<void()>& body, int repeats)
{
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        QElapsedTimer timer;
        timer.start();
        body();
        ms.push_back(double(timer.nsecsElapsed()) * 1e-6);
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

// Poses 0..count−1 of a made-up motion: bone b turns by up to 50° about an axis of its
// own, the rig moves by `shift`·t; pose 0 is the rest pose.
std::vector<SkeletonPose> madeUpMotion(const SkeletonRig& rig, int count, const glm::dvec3& shift)
{
    std::vector<SkeletonPose> motion;
    for (int t = 0; t < count; ++t) {
        const double s = double(t) / double(count - 1);
        SkeletonPose pose = restPose(rig);
        for (std::size_t b = 0; b < rig.bones.size(); ++b) {
            const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0 + double(b), 2.0 - double(b), 0.5 * double(b) + 1.0));
            pose.rotations[b] = glm::angleAxis(glm::radians(50.0) * s * (b % 2 ? -1.0 : 1.0), axis);
        }
        pose.rootTranslation = shift * s;
        motion.push_back(pose);
    }
    return motion;
}

std::vector<PosePositions> skinnedMotion(const TriangleMesh& mesh, const SkeletonRig& rig, const BoneWeights& weights,
                                         const std::vector<SkeletonPose>& motion)
{
    std::vector<PosePositions> poses;
    for (const SkeletonPose& pose : motion) {
        const std::vector<glm::vec3> p = posePositions(mesh.positions, rig, weights, pose, SkinningMethod::Lbs);
        poses.emplace_back(p.begin(), p.end());
    }
    return poses;
}

// Poses 3, 2, 1, 0, 4, 5, 6 of seven: the rest pose 0 moves to the middle.
std::vector<PosePositions> reordered(std::vector<PosePositions> poses)
{
    std::swap(poses[0], poses[3]);
    std::swap(poses[1], poses[2]);
    return poses;
}

} // namespace

class TestSkeletonPose : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void identityPoseReproducesTheRestMesh();
    void quarterTurnOfAnArmUnderLbs();
    void quarterTurnOfAnArmUnderDqs();
    void childBonesFollowTheirParents();
    void rootTranslationMovesEverything();
    void badPosesAreRefused();
    void skinningIsFastEnoughToDrag();
    void localAnglesAreInTheBonesFrame();
    void draggingTurnsTheBoneAboutItsPosedHead();
    void motionFitRecoversTheRigsOwnMotion();
    void motionFitMeasuresWhatNoPoseReaches();

private:
    TriangleMesh m_t;
    SkeletonRig m_rig;
    BoneWeights m_weights;
};

void TestSkeletonPose::initTestCase()
{
    m_t = test::makeTTube();
    m_rig = test::tRig();
    m_weights = boneHeatWeights(m_t, m_rig);
}

void TestSkeletonPose::identityPoseReproducesTheRestMesh()
{
    for (const SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        const std::vector<glm::vec3> posed = posePositions(m_t.positions, m_rig, m_weights, restPose(m_rig), method);
        QCOMPARE(posed, m_t.positions); // bit for bit
    }
    const TriangleMesh capsule = test::axisCapsule(1.0, 4.0, 6, 16, 24);
    const SkeletonRig chain = test::chainRig({-4.5, -1.5, 1.5, 4.5});
    const BoneWeights w = boneHeatWeights(capsule, chain);
    QCOMPARE(posePositions(capsule.positions, chain, w, restPose(chain), SkinningMethod::Dqs), capsule.positions);
}

// Only bone 1 (the right arm, head h at the junction) turns; the other bones stay at the
// identity. LBS: v' = (1 − w)·v + w·(R(v − h) + h) with w the vertex's weight of bone 1.
void TestSkeletonPose::quarterTurnOfAnArmUnderLbs()
{
    SkeletonPose pose = restPose(m_rig);
    pose.rotations[1] = kQuarterTurnZ;
    const std::vector<glm::vec3> posed = posePositions(m_t.positions, m_rig, m_weights, pose, SkinningMethod::Lbs);
    const glm::dvec3 h = m_rig.joints[0];
    std::size_t tips = 0;
    for (std::size_t v = 0; v < posed.size(); ++v) {
        const glm::dvec3 p(m_t.positions[v]);
        const double w = weightOf(m_weights, v, 1);
        const glm::dvec3 expected = (1.0 - w) * p + w * (kQuarterTurnZ * (p - h) + h);
        QVERIFY2(glm::length(glm::dvec3(posed[v]) - expected) < 1e-5,
                 qPrintable(QString("vertex %1: off by %2").arg(v).arg(glm::length(glm::dvec3(posed[v]) - expected))));
        if (p.x >= 5.5) { // the tip of the right arm now points up: (x, y) → (1 − y, 1 + x)
            QVERIFY(posed[v].y > 6.4f && posed[v].x > -1.1f && posed[v].x < 1.1f);
            ++tips;
        }
    }
    QVERIFY(tips > 20);
}

// DQS of motions that all fix h: the blend is the rotation about h by
// normalize((1 − w)·1 + w·q) (conjugation by the translation to h is linear).
void TestSkeletonPose::quarterTurnOfAnArmUnderDqs()
{
    SkeletonPose pose = restPose(m_rig);
    pose.rotations[1] = kQuarterTurnZ;
    const std::vector<glm::vec3> posed = posePositions(m_t.positions, m_rig, m_weights, pose, SkinningMethod::Dqs);
    const glm::dvec3 h = m_rig.joints[0];
    for (std::size_t v = 0; v < posed.size(); ++v) {
        const glm::dvec3 p(m_t.positions[v]);
        const double w = weightOf(m_weights, v, 1);
        const glm::dquat q = kQuarterTurnZ;
        const glm::dquat blend = glm::normalize(glm::dquat(1.0 - w + w * q.w, w * q.x, w * q.y, w * q.z));
        const glm::dvec3 expected = blend * (p - h) + h;
        QVERIFY2(glm::length(glm::dvec3(posed[v]) - expected) < 1e-5,
                 qPrintable(QString("vertex %1: off by %2").arg(v).arg(glm::length(glm::dvec3(posed[v]) - expected))));
        // DQS keeps the distance to the joint (no candy-wrapper collapse): |v' − h| = |v − h|.
        QVERIFY(std::abs(glm::length(glm::dvec3(posed[v]) - h) - glm::length(p - h)) < 1e-5);
    }
}

void TestSkeletonPose::childBonesFollowTheirParents()
{
    // Chain along y: joints at −4.5, −1.5, 1.5, 4.5. Bone 0 and bone 1 each turn a quarter
    // about z (x, y → −y, x): by hand, joint 1 turns about joint 0 to (−3, −4.5); joint 2
    // turns about joint 1's rest position to (−3, −1.5), then with bone 0 to (−3, −7.5);
    // joint 3 likewise to (−6, −1.5), then (−3, −10.5).
    const SkeletonRig chain = test::chainRig({-4.5, -1.5, 1.5, 4.5});
    SkeletonPose pose = restPose(chain);
    pose.rotations[0] = kQuarterTurnZ;
    pose.rotations[1] = kQuarterTurnZ;
    const std::vector<DualQuaternion> motions = boneMotions(chain, pose);
    const std::vector<glm::dvec3> joints = posedJoints(chain, motions);
    const std::vector<glm::dvec3> expected = {{0, -4.5, 0}, {-3, -4.5, 0}, {-3, -7.5, 0}, {-3, -10.5, 0}};
    for (std::size_t j = 0; j < 4; ++j)
        QVERIFY2(glm::length(joints[j] - expected[j]) < 1e-12,
                 qPrintable(QString("joint %1 at (%2, %3)").arg(j).arg(joints[j].x).arg(joints[j].y)));
    // A vertex bound rigidly to bone 2 moves with it (LBS and DQS alike).
    BoneWeights rigid;
    rigid.bones = {{2, -1, -1, -1}};
    rigid.weights = {{1.0f, 0.0f, 0.0f, 0.0f}};
    const std::vector<glm::vec3> rest = {{1.0f, 3.0f, 0.0f}};
    std::vector<glm::vec3> lbs, dqs;
    skinPositions(rest, rigid, motions, SkinningMethod::Lbs, lbs);
    skinPositions(rest, rigid, motions, SkinningMethod::Dqs, dqs);
    // Bone 2 is turned by 180° in total about z: (1, 3) relative to joint 2's rest
    // position (0, 1.5) is (1, 1.5), turned: (−1, −1.5), at joint 2's posed (−3, −7.5).
    QVERIFY(glm::length(glm::dvec3(lbs[0]) - glm::dvec3(-4.0, -9.0, 0.0)) < 1e-5);
    QVERIFY(glm::length(glm::dvec3(dqs[0]) - glm::dvec3(-4.0, -9.0, 0.0)) < 1e-5);
}

void TestSkeletonPose::rootTranslationMovesEverything()
{
    SkeletonPose pose = restPose(m_rig);
    pose.rootTranslation = {0.25, -1.0, 2.0};
    for (const SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        const std::vector<glm::vec3> posed = posePositions(m_t.positions, m_rig, m_weights, pose, method);
        for (std::size_t v = 0; v < posed.size(); ++v)
            QVERIFY(glm::length(glm::dvec3(posed[v]) - glm::dvec3(m_t.positions[v]) - pose.rootTranslation) < 1e-5);
    }
    const std::vector<glm::dvec3> joints = posedJoints(m_rig, boneMotions(m_rig, pose));
    for (std::size_t j = 0; j < joints.size(); ++j)
        QVERIFY(glm::length(joints[j] - m_rig.joints[j] - pose.rootTranslation) < 1e-12);
}

void TestSkeletonPose::badPosesAreRefused()
{
    SkeletonPose pose = restPose(m_rig);
    pose.rotations.pop_back();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)boneMotions(m_rig, pose));
    pose = restPose(m_rig);
    pose.rotations[2] = glm::dquat(0.0, 0.0, 0.0, 0.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)boneMotions(m_rig, pose));
    pose = restPose(m_rig);
    pose.rootTranslation.y = std::nan("");
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)boneMotions(m_rig, pose));
    SkeletonRig cyclic = m_rig;
    cyclic.bones[0].parentBone = 2;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)boneMotions(cyclic, restPose(cyclic)));
    BoneWeights tooFew = m_weights;
    tooFew.bones.pop_back();
    tooFew.weights.pop_back();
    std::vector<glm::vec3> out;
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument,
        skinPositions(m_t.positions, tooFew, boneMotions(m_rig, restPose(m_rig)), SkinningMethod::Lbs, out));
}

// Live dragging re-skins the whole mesh per mouse move: time it on 50k vertices with
// four influences each and 30 bones (printed; never fails on speed).
void TestSkeletonPose::skinningIsFastEnoughToDrag()
{
    const TriangleMesh sphere = makeUvSphere({0.0, 0.0, 0.0}, 5.0, 224, 224);
    QVERIFY(sphere.vertexCount() > 49000);
    std::vector<double> heights;
    for (int j = 0; j <= 30; ++j)
        heights.push_back(-5.0 + 10.0 * j / 30.0);
    const SkeletonRig chain = test::chainRig(heights);
    BoneWeights w;
    for (const glm::vec3& p : sphere.positions) {
        const int b = std::clamp(int((p.y + 5.0f) / 10.0f * 30.0f), 0, 29);
        w.bones.push_back({b, (b + 1) % 30, (b + 2) % 30, (b + 3) % 30});
        w.weights.push_back({0.55f, 0.25f, 0.15f, 0.05f});
    }
    SkeletonPose pose = restPose(chain);
    for (std::size_t b = 0; b < pose.rotations.size(); ++b)
        pose.rotations[b] = glm::angleAxis(0.05 * double(b), glm::normalize(glm::dvec3(1.0, 0.3, 0.2)));
    std::vector<glm::vec3> out;
    for (const SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs})
        for (const unsigned threads : {1u, 0u}) {
            const double ms = medianMs(
                [&] { skinPositions(sphere.positions, w, boneMotions(chain, pose), method, out, threads); }, 7);
            qInfo("%s, %u thread(s) (0 = all): %.2f ms for %zu vertices (median of 7)",
                  method == SkinningMethod::Lbs ? "LBS" : "DQS", threads, ms, sphere.vertexCount());
            for (const glm::vec3& p : out)
                QVERIFY(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        }
}

// The local frame has +Y along the bone: on a bone along world +x, a turn about local Y
// spins the bone in place and a turn about local X swings its tail off the axis. Angles
// come back as given, wrapped into (−180, 180].
void TestSkeletonPose::localAnglesAreInTheBonesFrame()
{
    SkeletonRig rig;
    rig.joints = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
    rig.parent = {-1, 0};
    rig.bones = {{0, 1, -1}};
    const glm::dvec3 tail(1.0, 0.0, 0.0);
    const glm::dquat spin = boneRotationFromLocalDegrees(rig, 0, {0.0, 90.0, 0.0});
    QVERIFY(glm::length(spin * tail - tail) < 1e-12);
    QVERIFY(std::abs(glm::angle(spin) - M_PI / 2.0) < 1e-9);
    const glm::dquat swing = boneRotationFromLocalDegrees(rig, 0, {90.0, 0.0, 0.0});
    QVERIFY(std::abs(glm::dot(swing * tail, tail)) < 1e-12);

    const glm::dvec3 degrees(10.0, 20.0, 30.0);
    const glm::dvec3 back = localDegreesOfBoneRotation(rig, 0, boneRotationFromLocalDegrees(rig, 0, degrees));
    QVERIFY2(glm::length(back - degrees) < 1e-9, qPrintable(QString("%1 %2 %3").arg(back.x).arg(back.y).arg(back.z)));
    const glm::dvec3 wrapped = localDegreesOfBoneRotation(rig, 0, boneRotationFromLocalDegrees(rig, 0, {0, 0, 190}));
    QVERIFY(glm::length(wrapped - glm::dvec3(0.0, 0.0, -170.0)) < 1e-9);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)boneRotationFromLocalDegrees(rig, 1, degrees));
}

// A chain along +y (joints at 0, 1, 2). Each drag turns the posed bone rigidly about its
// posed head, whatever its parent did before; a zero axis changes nothing.
void TestSkeletonPose::draggingTurnsTheBoneAboutItsPosedHead()
{
    const SkeletonRig rig = test::chainRig({0.0, 1.0, 2.0});
    SkeletonPose pose = restPose(rig);
    const glm::dvec3 z(0.0, 0.0, 1.0);
    const auto joints = [&] { return posedJoints(rig, boneMotions(rig, pose)); };
    const auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-12; };

    rotateBoneAboutAxis(rig, pose, 1, z, M_PI / 2.0);
    QVERIFY(near(joints()[1], {0.0, 1.0, 0.0}));
    QVERIFY(near(joints()[2], {-1.0, 1.0, 0.0}));
    rotateBoneAboutAxis(rig, pose, 0, z, M_PI / 2.0); // carries bone 1 along
    QVERIFY(near(joints()[1], {-1.0, 0.0, 0.0}));
    QVERIFY(near(joints()[2], {-1.0, -1.0, 0.0}));
    rotateBoneAboutAxis(rig, pose, 1, 3.0 * z, -M_PI / 2.0); // about its posed head (−1, 0, 0)
    QVERIFY(near(joints()[1], {-1.0, 0.0, 0.0}));
    QVERIFY(near(joints()[2], {-2.0, 0.0, 0.0}));

    const SkeletonPose before = pose;
    rotateBoneAboutAxis(rig, pose, 1, glm::dvec3(0.0), 1.0);
    QCOMPARE(pose.rotations, before.rotations);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, rotateBoneAboutAxis(rig, pose, 2, z, 1.0));
}

// A motion the rig itself made (a chain whose bones carry each other, and the T whose
// three bones share the root) is fitted back to within float rounding, from the middle
// pose as the rest pose too, so that the fit runs both ways from it.
void TestSkeletonPose::motionFitRecoversTheRigsOwnMotion()
{
    const TriangleMesh capsule = test::axisCapsule(1.0, 4.0, 6, 16, 24);
    const SkeletonRig chain = test::chainRig({-4.5, -1.5, 1.5, 4.5});
    const BoneWeights chainWeights = boneHeatWeights(capsule, chain);
    for (const auto& [mesh, rig, weights] : {std::tuple{&capsule, &chain, &chainWeights}, {&m_t, &m_rig, &m_weights}}) {
        const std::vector<SkeletonPose> motion = madeUpMotion(*rig, 7, glm::dvec3(0.8, -0.3, 0.5));
        const std::vector<PosePositions> poses = skinnedMotion(*mesh, *rig, *weights, motion);
        // The same motion with the rest pose in the middle: poses 3, 2, 1, rest, 4, 5, 6.
        const std::vector<PosePositions> middle = reordered(poses);
        for (const auto& [sequence, rest] : {std::pair{&poses, std::size_t(0)}, std::pair{&middle, std::size_t(3)}}) {
            const RigMotionFit fit = fitRigToMotion(*rig, *weights, *sequence, rest);
            QCOMPARE(fit.poses.size(), poses.size());
            QVERIFY2(fit.error.eRmsDiagonal < 1e-3, describeRigMotionFit(fit).c_str());
            QVERIFY(fit.error.maxDistance < 1e-4);
            const std::size_t last = motion.size() - 1;
            QVERIFY(glm::length(fit.poses[last].rootTranslation - motion[last].rootTranslation) < 1e-4);
        }
    }
}

// A pose no rotation of the rig reaches (the T turned by 30°, moved, and grown by 5 %)
// leaves an error, but no more than the rig turned and moved as a whole, the best pose
// one can write down.
void TestSkeletonPose::motionFitMeasuresWhatNoPoseReaches()
{
    const glm::dquat turn = glm::angleAxis(glm::radians(30.0), glm::dvec3(0.0, 0.0, 1.0));
    const glm::dvec3 shift(0.5, -0.2, 0.1);
    std::vector<PosePositions> poses(2, PosePositions(m_t.positions.begin(), m_t.positions.end()));
    for (glm::dvec3& p : poses[1])
        p = 1.05 * (turn * p) + shift;
    SkeletonPose whole = restPose(m_rig);
    std::fill(whole.rotations.begin(), whole.rotations.end(), turn);
    const glm::dvec3 head = m_rig.joints[std::size_t(m_rig.root)];
    whole.rootTranslation = shift - head + turn * head; // x ↦ turn·x + shift
    const std::vector<PosePositions> wholeMotion = skinnedMotion(m_t, m_rig, m_weights, {restPose(m_rig), whole});
    const double wholeError = measureSkinningError(poses, wholeMotion).eRms;

    const RigMotionFit fit = fitRigToMotion(m_rig, m_weights, poses, 0);
    const QByteArray text =
        QByteArray::fromStdString(describeRigMotionFit(fit) + ", the whole rig turned " + std::to_string(wholeError));
    qInfo("%s", text.constData());
    QVERIFY2(fit.error.eRms > 0.2 * wholeError, text);
    QVERIFY2(fit.error.eRms <= wholeError, text);
    QCOMPARE(fit.error.perPose[0], 0.0);
}

QTEST_GUILESS_MAIN(TestSkeletonPose)
#include "tst_skeleton_pose.moc"
