// An animation as a dynamic-rule history (core/animation/animation_chain.h): against the
// rest pose one set; against the previous pose one set per step from the rest pose, in
// either direction; the rest pose itself has no chain; each level pairs the right poses.
#include "core/animation/animation_chain.h"
#include "core/animation/pose_sets.h"

#include <QtTest>

using namespace trimlab;

namespace {

// A tetrahedron whose apex moves by `pose` along x: pose p differs from pose q in the
// three triangles at the apex, so a level's moved count tells whether it pairs two poses.
MeshAnimation movingTetrahedron(std::size_t poses, std::size_t rest)
{
    MeshAnimation animation;
    animation.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    for (std::size_t p = 0; p < poses; ++p)
        animation.poses.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2f + 0.1f * float(p), 0.2f, 1.0f}});
    animation.restPose = rest;
    requireWellFormed(animation);
    return animation;
}

// The apex x of one frame-class object of a level: the moved triangles at their current
// (kDynamicObjectCurrentOnly) or reference (kDynamicObjectReferenceOnly) place.
float apexXOf(const DynamicChainLevel& level, int object)
{
    const TriangleMesh& mesh = level.frame.scene.objects[std::size_t(object)].mesh;
    float x = -1.0f;
    for (const glm::vec3& p : mesh.positions)
        if (p.z == 1.0f)
            x = p.x;
    return x;
}

float currentApexX(const DynamicChainLevel& level)
{
    return apexXOf(level, kDynamicObjectCurrentOnly);
}

float referenceApexX(const DynamicChainLevel& level)
{
    return apexXOf(level, kDynamicObjectReferenceOnly);
}

float apexX(std::size_t pose)
{
    return 0.2f + 0.1f * float(pose);
}

} // namespace

class TestAnimationChain : public QObject {
    Q_OBJECT
private slots:
    void restReferenceIsOneSet();
    void previousReferenceStepsFromTheRestPose();
    void theRestPoseHasNoChain();
    void names();
    void poseSetsReferenceTheLastPoseOfTheSetBefore();
    void poseSetsSpanRestAndPrevious();
    void badPoseSetsAreRefusedWithTheReason();
};

void TestAnimationChain::restReferenceIsOneSet()
{
    const MeshAnimation a = movingTetrahedron(5, 0);
    const DynamicChain chain =
        animationChain(a, 4, PoseReference::Rest, DynamicRule::Confluent, StaticRule::Parity).value();
    QCOMPARE(chain.levels.size(), std::size_t(1));
    QCOMPARE(chain.baseRule, StaticRule::Parity);
    QCOMPARE(chain.levels[0].rule, DynamicRule::Confluent);
    QCOMPARE(chain.levels[0].frame.movedTriangles, std::size_t(3));
    QCOMPARE(currentApexX(chain.levels[0]), 0.2f + 0.1f * 4.0f);
}

void TestAnimationChain::previousReferenceStepsFromTheRestPose()
{
    const MeshAnimation a = movingTetrahedron(6, 2);
    const DynamicChain forward =
        animationChain(a, 5, PoseReference::Previous, DynamicRule::ConstructiveAdditive, StaticRule::AlternatingBorder)
            .value();
    QCOMPARE(forward.levels.size(), std::size_t(3)); // 2 -> 3, 3 -> 4, 4 -> 5
    for (std::size_t j = 0; j < 3; ++j) {
        QCOMPARE(forward.levels[j].rule, DynamicRule::ConstructiveAdditive);
        QCOMPARE(currentApexX(forward.levels[j]), 0.2f + 0.1f * float(3 + j));
    }
    const DynamicChain backward =
        animationChain(a, 0, PoseReference::Previous, DynamicRule::Confluent, StaticRule::Parity).value();
    QCOMPARE(backward.levels.size(), std::size_t(2)); // 2 -> 1, 1 -> 0
    QCOMPARE(currentApexX(backward.levels[0]), 0.2f + 0.1f * 1.0f);
    QCOMPARE(currentApexX(backward.levels[1]), 0.2f);
}

void TestAnimationChain::theRestPoseHasNoChain()
{
    const MeshAnimation a = movingTetrahedron(3, 1);
    for (PoseReference reference : {PoseReference::Rest, PoseReference::Previous})
        QVERIFY(!animationChain(a, 1, reference, DynamicRule::Confluent, StaticRule::Parity));
    QVERIFY_THROWS_EXCEPTION(
        std::out_of_range, (void)animationChain(a, 3, PoseReference::Rest, DynamicRule::Confluent, StaticRule::Parity));
}

void TestAnimationChain::names()
{
    for (PoseReference reference : {PoseReference::Rest, PoseReference::Previous})
        QCOMPARE(parsePoseReference(poseReferenceName(reference)), std::optional<PoseReference>(reference));
    QVERIFY(!parsePoseReference("next"));
}

// Sets from poses 1, 3 and 6 of eight (rest pose 0): a pose's chain has a level per set up
// to its own, each from the set's reference (the pose before its first) to the next set's
// reference, the last to the pose itself, each with its set's rule.
void TestAnimationChain::poseSetsReferenceTheLastPoseOfTheSetBefore()
{
    const MeshAnimation a = movingTetrahedron(8, 0);
    const std::vector<PoseSet> sets{
        {1, DynamicRule::Confluent}, {3, DynamicRule::ConstructiveAdditive}, {6, DynamicRule::ConstructiveSubtractive}};
    QVERIFY(!poseSetChain(a, 0, sets, StaticRule::Parity));
    const DynamicChain two = poseSetChain(a, 2, sets, StaticRule::Parity).value();
    QCOMPARE(two.levels.size(), std::size_t(1));
    QCOMPARE(referenceApexX(two.levels[0]), apexX(0));
    QCOMPARE(currentApexX(two.levels[0]), apexX(2));
    const DynamicChain seven = poseSetChain(a, 7, sets, StaticRule::Parity).value();
    QCOMPARE(seven.baseRule, StaticRule::Parity);
    QCOMPARE(seven.levels.size(), std::size_t(3));
    const std::size_t from[] = {0, 2, 5};
    const std::size_t to[] = {2, 5, 7};
    for (std::size_t j = 0; j < 3; ++j) {
        QCOMPARE(seven.levels[j].rule, sets[j].rule);
        QCOMPARE(referenceApexX(seven.levels[j]), apexX(from[j]));
        QCOMPARE(currentApexX(seven.levels[j]), apexX(to[j]));
    }
    QCOMPARE(setOfPose(sets, 5), std::size_t(1));
    QCOMPARE(setOfPose(sets, 6), std::size_t(2));
}

// One set from pose 1 is the rest reference; a set per pose is the previous reference.
void TestAnimationChain::poseSetsSpanRestAndPrevious()
{
    const MeshAnimation a = movingTetrahedron(6, 0);
    std::vector<PoseSet> perPose;
    for (std::size_t p = 1; p < 6; ++p)
        perPose.push_back({p, DynamicRule::Confluent});
    for (std::size_t pose = 1; pose < 6; ++pose) {
        const DynamicChain one = poseSetChain(a, pose, {{1, DynamicRule::Confluent}}, StaticRule::Parity).value();
        const DynamicChain rest =
            animationChain(a, pose, PoseReference::Rest, DynamicRule::Confluent, StaticRule::Parity).value();
        QCOMPARE(one.levels.size(), rest.levels.size());
        QCOMPARE(currentApexX(one.levels.back()), currentApexX(rest.levels.back()));
        const DynamicChain steps = poseSetChain(a, pose, perPose, StaticRule::Parity).value();
        const DynamicChain previous =
            animationChain(a, pose, PoseReference::Previous, DynamicRule::Confluent, StaticRule::Parity).value();
        QCOMPARE(steps.levels.size(), previous.levels.size());
        for (std::size_t j = 0; j < steps.levels.size(); ++j) {
            QCOMPARE(referenceApexX(steps.levels[j]), referenceApexX(previous.levels[j]));
            QCOMPARE(currentApexX(steps.levels[j]), currentApexX(previous.levels[j]));
        }
    }
}

void TestAnimationChain::badPoseSetsAreRefusedWithTheReason()
{
    std::string error;
    const std::optional<std::vector<PoseSet>> parsed = parsePoseSets("1:confluent,40:additive", error);
    QVERIFY(parsed);
    QCOMPARE(poseSetsText(*parsed), std::string("1:confluent,40:additive"));
    QVERIFY(!parsePoseSets("1:confluent,x:additive", error));
    QVERIFY2(error.find("'x'") != std::string::npos, error.c_str());
    QVERIFY(!parsePoseSets("1:union", error));
    QVERIFY2(error.find("unknown rule 'union'") != std::string::npos, error.c_str());
    QVERIFY(!parsePoseSets("3", error));
    QVERIFY(!parsePoseSets("", error));
    const MeshAnimation a = movingTetrahedron(5, 1);
    const auto refusal = [&](const std::vector<PoseSet>& sets) {
        try {
            requireValidPoseSets(sets, a.restPose, a.poseCount());
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    QVERIFY(refusal({{3, DynamicRule::Confluent}}).find("right after the rest pose 1, at pose 2") != std::string::npos);
    QVERIFY(refusal({{2, DynamicRule::Confluent}, {2, DynamicRule::Confluent}}).find("increasing") !=
            std::string::npos);
    QVERIFY(refusal({{2, DynamicRule::Confluent}, {5, DynamicRule::Confluent}}).find("poses 0 to 4") !=
            std::string::npos);
    QVERIFY(refusal({{2, DynamicRule::Confluent}, {4, DynamicRule::Confluent}}).empty());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)poseSetChain(a, 0, {{2, DynamicRule::Confluent}}, StaticRule::Parity));
}

QTEST_APPLESS_MAIN(TestAnimationChain)
#include "tst_animation_chain.moc"
