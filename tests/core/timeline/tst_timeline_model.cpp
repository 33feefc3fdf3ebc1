// The Timeline model: frames, sets of concurrent disjoint deformations, undo, the chain of
// reference frames, and the invariants appendFrame enforces.
#include "tst_timeline_fixtures.h"

#include "core/timeline/timeline.h"

#include <QtTest>

#include <limits>

using namespace trimlab;
using namespace trimlab::timeline;
using trimlab::test::frameTo;
using trimlab::test::gridMesh;

class TestTimelineModel : public QObject {
    Q_OBJECT
private slots:
    void startsWithOneEmptySet();
    void appendedFramesReconstructExactly();
    void invalidAppendsThrowAndChangeNothing_data();
    void invalidAppendsThrowAndChangeNothing();
    void removeLastFrameRestoresBits();
    void startSetOnlyRenamesAnEmptySet();
    void setsChainTheirReferenceFrames();
    void undoAcrossASetKeepsSetsContiguous();
    void restoreChecksItsParts();
    void outOfRangeAccessThrows();
};

void TestTimelineModel::startsWithOneEmptySet()
{
    const Timeline t(gridMesh(), DynamicRule::ConstructiveAdditive);
    QCOMPARE(t.frameCount(), 1);
    QCOMPARE(t.sets().size(), std::size_t(1));
    QCOMPARE(t.sets()[0].rule, DynamicRule::ConstructiveAdditive);
    QCOMPARE(t.sets()[0].firstFrame, 1);
    QCOMPARE(t.sets()[0].frameCount, 0);
    QCOMPARE(t.sets()[0].referenceFrame(), 0);
    QCOMPARE(t.setOfFrame(0), 0);
    QVERIFY(test::sameBits(t.positionsAt(0), gridMesh().positions));
    QCOMPARE(t.meshAt(0), gridMesh());
}

void TestTimelineModel::appendedFramesReconstructExactly()
{
    Timeline t(gridMesh());
    const float denormal = std::numeric_limits<float>::denorm_min();
    t.appendFrame(frameTo(t, {3, 9}, {{0.1f, -0.0f, denormal}, {1e-30f, 0.3f, -0.7f}}));
    const std::vector<glm::vec3> afterOne = t.currentPositions();
    t.appendFrame(frameTo(t, {3, 10}, {{0.2f, 0.2f, 0.2f}, {-0.0f, -0.0f, -0.0f}}));
    QCOMPARE(t.frameCount(), 3);
    QCOMPARE(t.sets()[0].frameCount, 2);

    std::vector<glm::vec3> expected = gridMesh().positions;
    QVERIFY(test::sameBits(t.positionsAt(0), expected));
    expected[3] = {0.1f, -0.0f, denormal};
    expected[9] = {1e-30f, 0.3f, -0.7f};
    QVERIFY(test::sameBits(t.positionsAt(1), expected));
    QVERIFY(test::sameBits(afterOne, expected));
    expected[3] = {0.2f, 0.2f, 0.2f};
    expected[10] = {-0.0f, -0.0f, -0.0f};
    QVERIFY(test::sameBits(t.positionsAt(2), expected));
    QVERIFY(test::sameBits(t.currentPositions(), expected));
    QCOMPARE(t.meshAt(2).triangles, gridMesh().triangles);
    QCOMPARE(t.setOfFrame(1), 0);
    QCOMPARE(t.setOfFrame(2), 0);
}

void TestTimelineModel::invalidAppendsThrowAndChangeNothing_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("before disagrees") << 0;
    QTest::newRow("before is +0 where the position is -0") << 1;
    QTest::newRow("vertex out of range") << 2;
    QTest::newRow("unsorted vertices") << 3;
    QTest::newRow("duplicate vertices") << 4;
    QTest::newRow("array sizes differ") << 5;
    QTest::newRow("after not finite") << 6;
    QTest::newRow("radius zero") << 7;
    QTest::newRow("drag not finite") << 8;
}

void TestTimelineModel::invalidAppendsThrowAndChangeNothing()
{
    QFETCH(int, kind);
    Timeline t(gridMesh());
    t.appendFrame(frameTo(t, {5}, {{0.5f, -0.0f, 0.25f}}));
    const Timeline before = t;
    Frame frame = frameTo(t, {4, 5}, {{1.0f, 1.0f, 1.0f}, {2.0f, 2.0f, 2.0f}});
    switch (kind) {
    case 0:
        frame.before[0].x += 0.001f;
        break;
    case 1:
        frame.before[1].y = 0.0f;
        break; // vertex 5 holds -0.0f: bits differ
    case 2:
        frame = frameTo(t, {4, 64}, {{}, {}});
        break;
    case 3:
        frame = frameTo(t, {5, 4}, {{}, {}});
        break;
    case 4:
        frame = frameTo(t, {4, 4}, {{}, {}});
        break;
    case 5:
        frame.after.pop_back();
        break;
    case 6:
        frame.after[0].z = std::numeric_limits<float>::quiet_NaN();
        break;
    case 7:
        frame.stroke.brush.radius = 0.0;
        break;
    case 8:
        frame.stroke.drag.x = std::numeric_limits<double>::infinity();
        break;
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, t.appendFrame(frame));
    QCOMPARE(t, before);
    QVERIFY(test::sameBits(t, before));
}

void TestTimelineModel::removeLastFrameRestoresBits()
{
    Timeline t(gridMesh());
    const Timeline empty = t;
    t.appendFrame(frameTo(t, {0, 1}, {{-0.0f, 0.5f, 0.5f}, {0.1f, 0.2f, 0.3f}}));
    const Timeline one = t;
    const Frame second = frameTo(t, {0}, {{0.0f, 0.5f, 0.5f}});
    t.appendFrame(second);
    QCOMPARE(t.removeLastFrame(), second);
    QCOMPARE(t, one);
    QVERIFY(test::sameBits(t.currentPositions(), one.currentPositions()));
    QVERIFY(std::signbit(t.currentPositions()[0].x)); // -0.0f restored, not +0.0f
    t.removeLastFrame();
    QCOMPARE(t, empty);
    QCOMPARE(t.sets().size(), std::size_t(1));
    QVERIFY_THROWS_EXCEPTION(std::logic_error, t.removeLastFrame());
}

void TestTimelineModel::startSetOnlyRenamesAnEmptySet()
{
    Timeline t(gridMesh());
    t.startSet(DynamicRule::ConstructiveSubtractive); // set 0 is empty: only its rule changes
    QCOMPARE(t.sets().size(), std::size_t(1));
    QCOMPARE(t.sets()[0].rule, DynamicRule::ConstructiveSubtractive);
    t.appendFrame(frameTo(t, {1}, {{0.0f, 0.0f, 0.5f}}));
    t.startSet(DynamicRule::ConstructiveIntersection);
    QCOMPARE(t.sets().size(), std::size_t(2));
    QCOMPARE(t.sets()[1].firstFrame, 2);
    QCOMPARE(t.sets()[1].referenceFrame(), 1);
    t.startSet(DynamicRule::HomogeneousConfluent); // still empty: renamed again
    QCOMPARE(t.sets().size(), std::size_t(2));
    QCOMPARE(t.sets()[1].rule, DynamicRule::HomogeneousConfluent);
    t.removeLastSetIfEmpty();
    QCOMPARE(t.sets().size(), std::size_t(1));
    t.removeLastSetIfEmpty(); // never removes the only set, nor a non-empty one
    QCOMPARE(t.sets().size(), std::size_t(1));
    t.setRule(0, DynamicRule::Confluent);
    QCOMPARE(t.sets()[0].rule, DynamicRule::Confluent);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, t.setRule(1, DynamicRule::Confluent));
}

// Sets {1, 2} additive, {3} subtractive, {4, 5} confluent, then an empty intersection set.
void TestTimelineModel::setsChainTheirReferenceFrames()
{
    Timeline t(gridMesh(), DynamicRule::ConstructiveAdditive);
    const auto stroke = [&t](std::uint32_t v) { t.appendFrame(frameTo(t, {v}, {{float(v), 1.0f, 1.0f}})); };
    stroke(1);
    stroke(2);
    t.startSet(DynamicRule::ConstructiveSubtractive);
    stroke(3);
    t.startSet(DynamicRule::Confluent);
    stroke(4);
    stroke(5);
    t.startSet(DynamicRule::ConstructiveIntersection);
    QCOMPARE(t.frameCount(), 6);
    QCOMPARE(t.sets().size(), std::size_t(4));
    const int expectedSet[] = {0, 0, 0, 1, 2, 2};
    for (int f = 0; f < 6; ++f)
        QCOMPARE(t.setOfFrame(f), expectedSet[f]);
    using Link = Timeline::ChainLink;
    const auto chain = [&t](int f) {
        std::vector<std::pair<int, DynamicRule>> out;
        for (const Link& link : t.chainTo(f))
            out.emplace_back(link.referenceFrame, link.rule);
        return out;
    };
    using Chain = std::vector<std::pair<int, DynamicRule>>;
    QCOMPARE(chain(0), (Chain{{0, DynamicRule::ConstructiveAdditive}}));
    QCOMPARE(chain(2), (Chain{{0, DynamicRule::ConstructiveAdditive}}));
    QCOMPARE(chain(3), (Chain{{0, DynamicRule::ConstructiveAdditive}, {2, DynamicRule::ConstructiveSubtractive}}));
    QCOMPARE(chain(5), (Chain{{0, DynamicRule::ConstructiveAdditive},
                              {2, DynamicRule::ConstructiveSubtractive},
                              {3, DynamicRule::Confluent}}));
    QCOMPARE(t.sets()[3].referenceFrame(), 5);
}

// Undoing strokes without undoing the set start keeps every set contiguous.
void TestTimelineModel::undoAcrossASetKeepsSetsContiguous()
{
    Timeline t(gridMesh());
    t.appendFrame(frameTo(t, {1}, {{0.0f, 0.0f, 0.5f}}));
    t.appendFrame(frameTo(t, {2}, {{0.0f, 0.0f, 0.5f}}));
    t.startSet(DynamicRule::ConstructiveAdditive);
    t.removeLastFrame(); // frame 2 belonged to set 0; the empty set 1 now starts after frame 1
    QCOMPARE(t.sets()[0].frameCount, 1);
    QCOMPARE(t.sets()[1].firstFrame, 2);
    QCOMPARE(t.sets()[1].referenceFrame(), 1);
    t.appendFrame(frameTo(t, {3}, {{0.0f, 0.0f, 0.5f}})); // goes to the last set
    QCOMPARE(t.sets()[1].frameCount, 1);
    QCOMPARE(t.setOfFrame(2), 1);
    const Timeline rebuilt = Timeline::restore(t.base(), {t.frame(1), t.frame(2)}, t.sets());
    QCOMPARE(rebuilt, t);
}

void TestTimelineModel::restoreChecksItsParts()
{
    Timeline t(gridMesh());
    t.appendFrame(frameTo(t, {1}, {{0.0f, 0.0f, 0.5f}}));
    const Frame f1 = t.frame(1);
    const auto set = [](int first, int count) { return DeformationSet{DynamicRule::Confluent, first, count}; };
    QCOMPARE(Timeline::restore(t.base(), {f1}, {set(1, 1)}), t);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)Timeline::restore(t.base(), {f1}, {}));
    QCOMPARE(Timeline::restore(TriangleMesh{}, {}, {}), Timeline());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)Timeline::restore(t.base(), {f1}, {set(1, 2)}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)Timeline::restore(t.base(), {f1}, {set(1, 0), set(3, 1)}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)Timeline::restore(t.base(), {f1, f1}, {set(1, 2)}));
    TriangleMesh broken = t.base();
    broken.triangles[0].y = 64;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)Timeline::restore(broken, {}, {set(1, 0)}));
    try {
        (void)Timeline::restore(t.base(), {f1, f1}, {set(1, 2)});
    } catch (const std::invalid_argument& error) {
        QVERIFY2(QString(error.what()).startsWith("frames[1]: "), error.what());
    }
}

void TestTimelineModel::outOfRangeAccessThrows()
{
    Timeline t(gridMesh());
    t.appendFrame(frameTo(t, {1}, {{0.0f, 0.0f, 0.5f}}));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.frame(0));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.frame(2));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.positionsAt(-1));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.positionsAt(2));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.setOfFrame(2));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)t.chainTo(2));
}

QTEST_GUILESS_MAIN(TestTimelineModel)
#include "tst_timeline_model.moc"
