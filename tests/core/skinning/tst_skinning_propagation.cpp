// Pose editing with propagation (thesis 4.1.3, eq. 4.18–4.19): editing pose e changes
// poses ≥ e exactly as eq. 4.18 composes them from the unchanged transforms, leaves
// earlier poses bit-identical, and works for new positions and for a changed bone.
#include "core/skinning/skinning_fitter.h"
#include "core/skinning/skinning_propagation.h"
#include "core/skinning/skinning_reconstruction.h"

#include "skinning_fixtures.h"

#include <QtTest>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr unsigned kRings = 12, kSides = 10, kBones = 3;
constexpr std::size_t kPoses = 6;
constexpr std::size_t kEdited = 3;

SkinningModel fittedModel(SkinningMethod method, SkinningChain chain = SkinningChain::PoseToPose)
{
    SkinningFitOptions options;
    options.method = method;
    options.chain = chain;
    return fitSkinning(bendingTube(kRings, kSides, kPoses), tubeSegments(kRings, kSides, kBones), options).model;
}

// Pose `pose` of `model` with the far end of the tube lifted.
PosePositions liftedPose(const SkinningModel& model, std::size_t pose)
{
    PosePositions p = reconstructPose(model, pose);
    for (std::size_t j = 0; j < p.size(); ++j)
        p[j].z += 0.02 * model.restPositions[j].x * model.restPositions[j].x;
    return p;
}

// Eq. 4.18 against the edited model, and bit-identity before the edit.
void checkPropagation(const SkinningModel& original, const SkinningModel& edited, std::size_t e)
{
    const std::vector<PosePositions> before = reconstructPoses(original);
    const std::vector<PosePositions> after = reconstructPoses(edited);
    const double scale = 10.0; // the tube's size
    for (std::size_t t = 0; t < kPoses; ++t) {
        if (t < e) {
            QVERIFY2(after[t] == before[t], qPrintable(QString("pose %1 changed").arg(t)));
            continue;
        }
        QVERIFY2(after[t] != before[t], qPrintable(QString("pose %1 did not follow the edit").arg(t)));
        for (std::size_t j = 0; j < original.vertexCount(); ++j) {
            const Affine3 expected = propagatedRestToPose(original, j, t, e, blendedTransform(edited, e, j));
            const glm::dvec3 p = expected.apply(original.restPositions[j]);
            QVERIFY(glm::length(p - after[t][j]) < 1e-12 * scale);
        }
    }
    for (std::size_t t = 0; t < kPoses; ++t)
        if (t != e) {
            QVERIFY(edited.affine.empty() || edited.affine[t] == original.affine[t]); // no refit
            QVERIFY(edited.rigid.empty() || edited.rigid[t] == original.rigid[t]);
        }
}

} // namespace

class TestSkinningPropagation : public QObject {
    Q_OBJECT
private slots:
    void editedPositionsPropagate();
    void changedBonePropagates();
    void chainProductMatchesEquation419();
    void restPoseAndClassicalEdits();
    void badEditsAreRejected();
};

void TestSkinningPropagation::editedPositionsPropagate()
{
    for (SkinningMethod method : {SkinningMethod::Lbs, SkinningMethod::Dqs}) {
        const SkinningModel model = fittedModel(method);
        const PosePositions target = liftedPose(model, kEdited);
        const SkinningModel edited = editPose(model, kEdited, target);
        checkPropagation(model, edited, kEdited);
        // The edited pose itself moves towards the requested positions.
        const PosePositions got = reconstructPose(edited, kEdited);
        const PosePositions old = reconstructPose(model, kEdited);
        double toTargetNew = 0.0, toTargetOld = 0.0;
        for (std::size_t j = 0; j < got.size(); ++j) {
            toTargetNew += glm::dot(got[j] - target[j], got[j] - target[j]);
            toTargetOld += glm::dot(old[j] - target[j], old[j] - target[j]);
        }
        QVERIFY(toTargetNew < 0.5 * toTargetOld);
    }
}

void TestSkinningPropagation::changedBonePropagates()
{
    const SkinningModel lbs = fittedModel(SkinningMethod::Lbs);
    Affine3 changed = lbs.affine[kEdited][2];
    changed.translation += glm::dvec3(0.0, 0.3, 0.0);
    checkPropagation(lbs, setBoneTransform(lbs, kEdited, 2, changed), kEdited);

    const SkinningModel dqs = fittedModel(SkinningMethod::Dqs);
    const DualQuaternion turn = dualQuaternionFromRigid(glm::angleAxis(0.2, glm::dvec3(0, 0, 1)), glm::dvec3(0.0));
    checkPropagation(dqs, setBoneTransform(dqs, kEdited, 2, turn * dqs.rigid[kEdited][2]), kEdited);
}

void TestSkinningPropagation::chainProductMatchesEquation419()
{
    const SkinningModel model = fittedModel(SkinningMethod::Lbs);
    std::vector<Affine3> t;
    for (std::size_t j = 0; j < model.vertexCount(); j += 7) {
        vertexRestToPose(model, j, t);
        for (std::size_t pose = 1; pose < kPoses; ++pose) {
            const Affine3 product = chainProduct(model, j, pose, 1); // T^{t,1} = T^t
            QVERIFY(glm::length(product.apply(model.restPositions[j]) - t[pose].apply(model.restPositions[j])) < 1e-12);
        }
        QCOMPARE(chainProduct(model, j, 0, 1), Affine3{}); // empty range T^{e−1,1} for e = 1
        QCOMPARE(chainProduct(model, j, 2, 2), blendedTransform(model, 2, j));
    }
}

void TestSkinningPropagation::restPoseAndClassicalEdits()
{
    // Editing the rest pose moves every pose (rest-pose editing, thesis Fig. 4.2).
    const SkinningModel model = fittedModel(SkinningMethod::Lbs);
    const SkinningModel rest = editPose(model, 0, liftedPose(model, 0));
    const std::vector<PosePositions> a = reconstructPoses(model), b = reconstructPoses(rest);
    for (std::size_t t = 0; t < kPoses; ++t)
        QVERIFY(a[t] != b[t]);
    // A classical (rest-to-pose) model: only the edited pose changes.
    const SkinningModel classical = fittedModel(SkinningMethod::Lbs, SkinningChain::RestToPose);
    const SkinningModel edited = editPose(classical, kEdited, liftedPose(classical, kEdited));
    const std::vector<PosePositions> c = reconstructPoses(classical), d = reconstructPoses(edited);
    for (std::size_t t = 0; t < kPoses; ++t)
        QCOMPARE(c[t] == d[t], t != kEdited);
}

void TestSkinningPropagation::badEditsAreRejected()
{
    const SkinningModel model = fittedModel(SkinningMethod::Lbs);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)editPose(model, kPoses, model.restPositions));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)editPose(model, 1, PosePositions(3)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)setBoneTransform(model, 1, kBones, Affine3{}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)setBoneTransform(model, 1, 0, DualQuaternion{}));
}

QTEST_APPLESS_MAIN(TestSkinningPropagation)
#include "tst_skinning_propagation.moc"
