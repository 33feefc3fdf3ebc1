// The dynamic rules of thesis 8.1.1 (table-driven, written out from the formulas by hand)
// and the dynamic walk of Algorithms 8.11–8.13 on hand-built rays.
#include "core/catalog/demo_scenes.h"
#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_frame_scene.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/dynamic_reference_sequence.h"
#include "core/scene/shape_generators.h"
#include "core/trim/dynamic_rule.h"
#include "core/trim/dynamic_walk.h"
#include "core/trim/reference_renderer.h"
#include "core/trim/trim_membership.h"

#include <glm/geometric.hpp>

#include <QtTest>

using namespace trimlab;

namespace {

RayHit hit(double t, int object, int facing)
{
    RayHit h;
    h.t = t;
    h.objectId = object;
    h.primitiveId = int(t * 10);
    h.facing = facing;
    return h;
}

KeptSpan spanFrom(double tStart)
{
    return KeptSpan{false, tStart, 100.0, false};
}

// Figure 8.7 along one ray: the reference has a solid part [2,4) (w = 1) and a negative
// part [6,8) (w = −1); the current frame extends the solid's far side from 4 to 7, into
// the negative part. Objects: 0 both frames, 1 current only, 2 reference only.
std::vector<RayHit> extendedTipRay()
{
    return {hit(2, 0, +1), hit(4, 2, -1), hit(6, 0, -1), hit(7, 1, -1), hit(8, 0, +1)};
}

} // namespace

class TestDynamicRules : public QObject {
    Q_OBJECT
private slots:
    void ruleTable_data();
    void ruleTable();
    void namesRoundTrip();
    void extendedTipKeepsTheSweptNegativeRegion();
    void staticRuleTrimsTheSweptNegativeRegion();
    void referenceOnlyHitsAreNeverShown();
    void characterizationRecordsEveryCurrentInterval();
    void characterizationOverflowMakesPixelsUnresolved();
    void overflowIsForgottenWhereNoReferenceHitIsBehind();
    void unchangedFrameMatchesTheStaticRule();
    void frameSceneSplitsMovedTriangles();
    void trimmedOffPartsAreFound();
    void carriedSequenceEqualsTheWholeChain();
};

void TestDynamicRules::ruleTable_data()
{
    QTest::addColumn<int>("rule");
    QTest::addColumn<int>("wRef");
    QTest::addColumn<int>("wCur");
    QTest::addColumn<bool>("refIn");
    QTest::addColumn<bool>("expected");
    // constructive: i' = i op changed; confluent: unchanged keeps i, grew -> in, shrank -> out
    struct Row {
        DynamicRule rule;
        int wr, wc;
        bool in, out;
    };
    const Row rows[] = {
        {DynamicRule::ConstructiveAdditive, 0, 0, false, false},
        {DynamicRule::ConstructiveAdditive, 0, 1, false, true},
        {DynamicRule::ConstructiveAdditive, 1, 0, false, true},
        {DynamicRule::ConstructiveAdditive, 1, 1, true, true},
        {DynamicRule::ConstructiveSubtractive, 1, 1, true, true},
        {DynamicRule::ConstructiveSubtractive, 1, 2, true, false},
        {DynamicRule::ConstructiveSubtractive, 1, 0, false, false},
        {DynamicRule::ConstructiveIntersection, 1, 1, true, false},
        {DynamicRule::ConstructiveIntersection, 0, 1, true, true},
        {DynamicRule::ConstructiveIntersection, 0, 1, false, false},
        {DynamicRule::Confluent, 3, 3, true, true},
        {DynamicRule::Confluent, 3, 3, false, false},
        {DynamicRule::Confluent, -1, 0, false, true},
        {DynamicRule::Confluent, 2, 1, true, false},
        {DynamicRule::HomogeneousConfluent, 0, -1, true, false},
        {DynamicRule::HomogeneousConfluent, 0, 1, false, true},
    };
    int i = 0;
    for (const Row& r : rows)
        QTest::newRow(qPrintable(QString("%1 %2").arg(QString::fromLatin1(dynamicRuleName(r.rule).data())).arg(i++)))
            << int(r.rule) << r.wr << r.wc << r.in << r.out;
}

void TestDynamicRules::ruleTable()
{
    QFETCH(int, rule);
    QFETCH(int, wRef);
    QFETCH(int, wCur);
    QFETCH(bool, refIn);
    QFETCH(bool, expected);
    QCOMPARE(dynamicInterior(DynamicRule(rule), wRef, wCur, refIn), expected);
}

void TestDynamicRules::namesRoundTrip()
{
    for (DynamicRule rule :
         {DynamicRule::ConstructiveAdditive, DynamicRule::ConstructiveSubtractive,
          DynamicRule::ConstructiveIntersection, DynamicRule::Confluent, DynamicRule::HomogeneousConfluent})
        QCOMPARE(parseDynamicRule(dynamicRuleName(rule)), std::optional<DynamicRule>(rule));
    QVERIFY(!parseDynamicRule("union").has_value());
}

void TestDynamicRules::extendedTipKeepsTheSweptNegativeRegion()
{
    // Seen from inside the swept region (clip at 5): under the confluent rule [4,7) was
    // crossed by the surface moving outward, so it is interior; the first class change is
    // at the moved surface (t = 7), not at the unchanged crossing at t = 6.
    const std::vector<RayHit> hits = extendedTipRay();
    TrimSettings settings;
    const ReferenceClassification base{nullptr, StaticRule::AlternatingBorder};
    const DynamicWalkResult result = walkDynamicRay(hits, spanFrom(5.0), settings, DynamicRule::Confluent, base);
    QVERIFY(!result.unresolved);
    QCOMPARE(result.walk.windingAtStart, 1);
    QCOMPARE(result.walk.shownIndex, std::ptrdiff_t(3));
}

void TestDynamicRules::staticRuleTrimsTheSweptNegativeRegion()
{
    // The same current surface under the static alternating border rule: [6,7) has w = 0
    // and is exterior, so the surface at t = 6 is shown (the "unintuitive hole").
    std::vector<RayHit> current;
    for (const RayHit& h : extendedTipRay()) {
        if (h.objectId != kDynamicObjectReferenceOnly)
            current.push_back(h);
    }
    TrimSettings settings;
    const TrimWalk walk = walkTrimRay(current, spanFrom(5.0), settings);
    QCOMPARE(walk.shownIndex, std::ptrdiff_t(1));
    QCOMPARE(current[1].t, 6.0);
}

void TestDynamicRules::referenceOnlyHitsAreNeverShown()
{
    TrimSettings settings;
    settings.trimEnabled = false;
    const ReferenceClassification base{nullptr, StaticRule::AlternatingBorder};
    const DynamicWalkResult result =
        walkDynamicRay(extendedTipRay(), spanFrom(3.0), settings, DynamicRule::Confluent, base);
    QCOMPARE(result.walk.shownIndex, std::ptrdiff_t(2)); // t = 6, skipping reference-only t = 4
}

void TestDynamicRules::characterizationRecordsEveryCurrentInterval()
{
    // Current hits behind each interval: 4 (before t=2), 3, 2 (after 6), 1 (after 7), 0.
    const ReferenceClassification base{nullptr, StaticRule::AlternatingBorder};
    const PartitionCharacterization c = characterizeDynamicRay(extendedTipRay(), DynamicRule::Confluent, base);
    QVERIFY(!c.overflowed);
    QCOMPARE(c.interior(4), false); // in front of everything
    QCOMPARE(c.interior(3), true);  // [2,6): the solid and the swept part
    QCOMPARE(c.interior(2), true);  // [6,7): swept into the negative region: kept (w = 0)
    QCOMPARE(c.interior(1), false); // [7,8): untouched negative region (w = −1)
    QCOMPARE(c.interior(0), false);

    // A second set with nothing moved keeps exactly that classification.
    std::vector<RayHit> unchanged;
    for (const RayHit& h : extendedTipRay()) {
        if (h.objectId != kDynamicObjectReferenceOnly)
            unchanged.push_back(RayHit{h.t, kDynamicObjectBoth, h.primitiveId, h.facing, 0.0, 0.0});
    }
    const ReferenceClassification previous{&c, StaticRule::AlternatingBorder};
    const PartitionCharacterization again = characterizeDynamicRay(unchanged, DynamicRule::Confluent, previous);
    QCOMPARE(again, c);
}

void TestDynamicRules::characterizationOverflowMakesPixelsUnresolved()
{
    std::vector<RayHit> deep;
    for (int i = 0; i < PartitionCharacterization::kLayers; ++i)
        deep.push_back(hit(1.0 + i, kDynamicObjectBoth, i % 2 == 0 ? +1 : -1));
    const ReferenceClassification base{nullptr, StaticRule::AlternatingBorder};
    const PartitionCharacterization c = characterizeDynamicRay(deep, DynamicRule::Confluent, base);
    QVERIFY(c.overflowed); // 257 intervals do not fit in 256 bits
    TrimSettings settings;
    const ReferenceClassification previous{&c, StaticRule::AlternatingBorder};
    const DynamicWalkResult result = walkDynamicRay(deep, spanFrom(0.5), settings, DynamicRule::Confluent, previous);
    QVERIFY(result.unresolved);
    QCOMPARE(result.walk.shownIndex, std::ptrdiff_t(-1));
}

// The interval behind every reference hit is outside under every rule, so a ray that has
// no reference hit (the surface left the pixel) or only current hits (a new surface
// arrived) is exact although the reference characterization overflowed; and its own
// characterization no longer carries the overflow to the next frame.
void TestDynamicRules::overflowIsForgottenWhereNoReferenceHitIsBehind()
{
    std::vector<RayHit> deep;
    for (int i = 0; i < PartitionCharacterization::kLayers; ++i)
        deep.push_back(hit(1.0 + i, kDynamicObjectBoth, i % 2 == 0 ? +1 : -1));
    const ReferenceClassification base{nullptr, StaticRule::AlternatingBorder};
    const PartitionCharacterization overflowed = characterizeDynamicRay(deep, DynamicRule::Confluent, base);
    QVERIFY(overflowed.overflowed);
    const ReferenceClassification previous{&overflowed, StaticRule::AlternatingBorder};
    TrimSettings settings;

    const DynamicWalkResult empty = walkDynamicRay({}, spanFrom(0.5), settings, DynamicRule::Confluent, previous);
    QVERIFY(!empty.unresolved);
    QCOMPARE(empty.walk.shownIndex, std::ptrdiff_t(-1));
    QVERIFY(!characterizeDynamicRay({}, DynamicRule::Confluent, previous).overflowed);

    const std::vector<RayHit> arrived{hit(2.0, kDynamicObjectCurrentOnly, +1), hit(3.0, kDynamicObjectCurrentOnly, -1)};
    const DynamicWalkResult result = walkDynamicRay(arrived, spanFrom(0.5), settings, DynamicRule::Confluent, previous);
    QVERIFY(!result.unresolved);
    QCOMPARE(result.walk.shownIndex, std::ptrdiff_t(0)); // the new surface, entered at t = 2
    const PartitionCharacterization next = characterizeDynamicRay(arrived, DynamicRule::Confluent, previous);
    QVERIFY(!next.overflowed);
    QCOMPARE(next.interior(1), true); // [2, 3): inside the new surface
    QCOMPARE(next.interior(0), false);

    // A ray that still crosses reference surfaces needs their classes: still unresolved.
    const std::vector<RayHit> stayed{hit(2.0, kDynamicObjectBoth, +1), hit(3.0, kDynamicObjectBoth, -1)};
    QVERIFY(walkDynamicRay(stayed, spanFrom(0.5), settings, DynamicRule::Confluent, previous).unresolved);
}

void TestDynamicRules::unchangedFrameMatchesTheStaticRule()
{
    // With nothing moved, every dynamic rule that keeps unchanged points (all but the
    // intersection rule) shows exactly what the static rule shows.
    const Scene scene = *makeDemoScene("pushed-sphere");
    const SceneObject& object = scene.objects.front();
    const DynamicChain chain =
        makeDynamicChain(object.mesh.triangles, {object.mesh.positions, object.mesh.positions},
                         {DynamicRule::Confluent}, StaticRule::AlternatingBorder, object.modelMatrix);
    QCOMPARE(chain.levels.front().frame.movedTriangles, std::size_t(0));
    const Camera camera = fitCamera(scene.worldBounds(), 48.0 / 36.0);
    TrimSettings settings;
    const ReferenceResult expected = ReferenceRenderer(scene).render(camera, 48, 36, settings);
    const ReferenceResult actual = DynamicReferenceRenderer(chain).render(camera, 48, 36, settings);
    int covered = 0;
    for (std::size_t i = 0; i < expected.trim.pixels.size(); ++i) {
        const TrimPixel& e = expected.trim.pixels[i];
        const TrimPixel& a = actual.trim.pixels[i];
        QCOMPARE(a.primitiveId, e.primitiveId);
        QCOMPARE(a.facing, e.facing);
        QCOMPARE(a.windingAtStart, e.windingAtStart);
        covered += e.covered() ? 1 : 0;
    }
    QVERIFY(covered > 100);
}

void TestDynamicRules::frameSceneSplitsMovedTriangles()
{
    const std::vector<glm::uvec3> triangles{{0, 1, 2}, {1, 3, 2}};
    const std::vector<glm::vec3> reference{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    std::vector<glm::vec3> current = reference;
    current[3].z = 0.5f; // moves only the second triangle
    const DynamicFrameScene frame = makeDynamicFrameScene(triangles, reference, current);
    QCOMPARE(frame.scene.objects.size(), std::size_t(3));
    QCOMPARE(frame.movedTriangles, std::size_t(1));
    QCOMPARE(frame.meshTriangle[kDynamicObjectBoth], std::vector<std::uint32_t>{0});
    QCOMPARE(frame.meshTriangle[kDynamicObjectCurrentOnly], std::vector<std::uint32_t>{1});
    QCOMPARE(frame.meshTriangle[kDynamicObjectReferenceOnly], std::vector<std::uint32_t>{1});
    QCOMPARE(frame.scene.objects[kDynamicObjectReferenceOnly].mesh.positions[3].z, 0.0f);
    QCOMPARE(frame.scene.objects[kDynamicObjectCurrentOnly].mesh.positions[3].z, 0.5f);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)makeDynamicFrameScene(triangles, reference, std::vector<glm::vec3>(3)));
}

void TestDynamicRules::trimmedOffPartsAreFound()
{
    // The pushed sphere under the alternating border rule (nothing moved yet): the south
    // pole lies inside the finger (w = 0 on both sides: the hole) and the finger's tip
    // below the sphere bounds w = −1 (exterior too): both are trimmed off; the sphere's
    // widest vertex is on the trim.
    const Scene scene = *makeDemoScene("pushed-sphere");
    const TriangleMesh& mesh = scene.objects.front().mesh;
    const DynamicChain chain = makeDynamicChain(mesh.triangles, {mesh.positions, mesh.positions},
                                                {DynamicRule::HomogeneousConfluent}, StaticRule::AlternatingBorder);
    const std::vector<glm::vec3> normals = vertexNormals(mesh);
    auto vertexNear = [&](const glm::dvec3& target) {
        std::size_t best = 0;
        for (std::size_t v = 1; v < mesh.positions.size(); ++v)
            if (glm::distance(glm::dvec3(mesh.positions[v]), target) <
                glm::distance(glm::dvec3(mesh.positions[best]), target))
                best = v;
        return best;
    };
    const std::size_t southPole = vertexNear({0.0, -1.0, 0.0});
    const std::size_t equator = vertexNear({1.0, 0.0, 0.0});
    const std::size_t fingerTip = vertexNear({0.0, -1.6, 0.0});
    std::vector<glm::dvec3> points, pointNormals;
    for (std::size_t v : {southPole, equator, fingerTip}) {
        points.emplace_back(mesh.positions[v]);
        pointNormals.emplace_back(normals[v]);
    }
    const std::vector<bool> onTrim = pointsOnTrim(DynamicReferenceRenderer(chain), points, pointNormals, 1e-4);
    QCOMPARE(onTrim, (std::vector<bool>{false, true, false}));
}

QTEST_APPLESS_MAIN(TestDynamicRules)
// Two balls moving into each other over four poses, against the previous pose under the
// confluent rule, parity on the first pose, cut open through the centres: the sequence that
// carries each pixel's characterization from level to level gives, at every pose, exactly
// the image of DynamicReferenceRenderer over the whole chain. The history matters: from
// the third pose on, a chain of the last step alone (the previous pose classified by
// parity) gives another image.
void TestDynamicRules::carriedSequenceEqualsTheWholeChain()
{
    const double offsets[] = {1.4, 1.0, 0.7, 0.45};
    std::vector<std::vector<glm::vec3>> frames;
    std::vector<glm::uvec3> triangles;
    for (double offset : offsets) {
        TriangleMesh balls = makeIcosphere(glm::dvec3(-offset, 0.0, 0.0), 1.0, 2);
        appendMesh(balls, makeIcosphere(glm::dvec3(offset, 0.1, 0.0), 1.0, 2));
        frames.push_back(balls.positions);
        triangles = balls.triangles;
    }
    constexpr int kWidth = 96;
    constexpr int kHeight = 64;
    Bounds bounds;
    for (const auto& frame : frames)
        for (const glm::vec3& p : frame)
            bounds.extend(glm::dvec3(p));
    const Camera camera = withDepthRange(fitCamera(bounds, double(kWidth) / kHeight), bounds);
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};

    DynamicReferenceSequence sequence(camera, kWidth, kHeight, StaticRule::Parity, 2);
    int historyDifferences = 0;
    for (std::size_t pose = 1; pose < frames.size(); ++pose) {
        const std::vector<std::vector<glm::vec3>> prefix(frames.begin(), frames.begin() + std::ptrdiff_t(pose) + 1);
        const DynamicChain whole = makeDynamicChain(
            triangles, prefix, std::vector<DynamicRule>(pose, DynamicRule::Confluent), StaticRule::Parity);
        const ReferenceResult carried = sequence.renderNext(whole.levels.back(), settings);
        const ReferenceResult expected = DynamicReferenceRenderer(whole).render(camera, kWidth, kHeight, settings, 2);
        int covered = 0;
        for (std::size_t i = 0; i < expected.trim.pixels.size(); ++i) {
            const TrimPixel& a = carried.trim.pixels[i];
            const TrimPixel& b = expected.trim.pixels[i];
            QVERIFY2(a.objectId == b.objectId && a.primitiveId == b.primitiveId && a.viewDepth == b.viewDepth &&
                         a.windingAtStart == b.windingAtStart && a.unresolved == b.unresolved,
                     qPrintable(QStringLiteral("pose %1, pixel %2").arg(pose).arg(i)));
            covered += b.covered() ? 1 : 0;
        }
        QVERIFY2(covered > kWidth * kHeight / 20, qPrintable(QString::number(covered)));
        const DynamicChain lastStep =
            makeDynamicChain(triangles, {frames[pose - 1], frames[pose]}, {DynamicRule::Confluent}, StaticRule::Parity);
        const ReferenceResult alone = DynamicReferenceRenderer(lastStep).render(camera, kWidth, kHeight, settings, 2);
        for (std::size_t i = 0; i < expected.trim.pixels.size(); ++i)
            historyDifferences += alone.trim.pixels[i].primitiveId != expected.trim.pixels[i].primitiveId ||
                                          alone.trim.pixels[i].objectId != expected.trim.pixels[i].objectId
                                      ? 1
                                      : 0;
    }
    QCOMPARE(sequence.levelsSeen(), frames.size() - 1);
    QVERIFY2(historyDifferences > 20, qPrintable(QString::number(historyDifferences)));
}

#include "tst_dynamic_rules.moc"
