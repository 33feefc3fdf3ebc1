// An animation as a dynamic-rule history (core/animation/animation_chain.h): against the
// rest pose one set; against the previous pose one set per step from the rest pose, in
// either direction; the rest pose itself has no chain; each level pairs the right poses.
#include "core/animation/animation_chain.h"

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

// The apex x of a level's current frame (the moved triangles at their current place).
float currentApexX(const DynamicChainLevel& level)
{
    const TriangleMesh& current = level.frame.scene.objects[std::size_t(kDynamicObjectCurrentOnly)].mesh;
    float x = -1.0f;
    for (const glm::vec3& p : current.positions)
        if (p.z == 1.0f)
            x = p.x;
    return x;
}

} // namespace

class TestAnimationChain : public QObject {
    Q_OBJECT
private slots:
    void restReferenceIsOneSet();
    void previousReferenceStepsFromTheRestPose();
    void theRestPoseHasNoChain();
    void names();
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
    QVERIFY_THROWS_EXCEPTION(std::out_of_range,
                             (void)animationChain(a, 3, PoseReference::Rest, DynamicRule::Confluent, StaticRule::Parity));
}

void TestAnimationChain::names()
{
    for (PoseReference reference : {PoseReference::Rest, PoseReference::Previous})
        QCOMPARE(parsePoseReference(poseReferenceName(reference)), std::optional<PoseReference>(reference));
    QVERIFY(!parsePoseReference("next"));
}

QTEST_APPLESS_MAIN(TestAnimationChain)
#include "tst_animation_chain.moc"
