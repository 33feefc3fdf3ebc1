// The inspection extensions of walkTrimRay (capping, n-ary CSG on per-object windings,
// collision flags, coplanar counts) on hand-written hit lists, every answer derived by
// hand in the comments. Notation as in tst_trim_walk.cpp: F enters (w+1), B exits (w-1);
// per-object windings are counted from the far side like the sum.
#include "core/trim/trim_walk.h"

#include <QtTest>

#include <vector>

using namespace trimlab;

namespace {

constexpr int F = 1;
constexpr int B = -1;

RayHit hit(double t, int facing, int objectId = 0, int primitiveId = 0)
{
    return {t, objectId, primitiveId, facing, 0.25, 0.5};
}

KeptSpan fromNear(double tEnd = 100.0)
{
    return {false, 0.1, tEnd, true};
}

// A span starting at clipping plane `plane` (a cap can show there).
KeptSpan atPlane(double tStart, int plane, double tEnd = 100.0)
{
    return {false, tStart, tEnd, false, plane, -1};
}

TrimSettings csg(const char* expression, StaticRule rule = StaticRule::PositiveIndex)
{
    TrimSettings s;
    s.rule = rule;
    std::string error;
    const std::optional<CsgExpression> e = parseCsgExpression(expression, &error);
    if (!e)
        qFatal("bad test expression %s: %s", expression, error.c_str());
    s.csg.expression = *e;
    return s;
}

TrimSettings capped(TrimSettings s)
{
    s.cap.enabled = true;
    s.clip = ClipPlane{true, {0.0, 0.0, 1.0}, 0.0}; // any enabled plane: capping() needs one
    return s;
}

// Two balls on one ray: object 0 spans t in [2, 6], object 1 spans [4, 8].
const std::vector<RayHit> kTwoBalls = {hit(2, F, 0, 10), hit(4, F, 1, 20), hit(6, B, 0, 11), hit(8, B, 1, 21)};
// Three balls: 0 in [2, 10], 1 in [3, 5], 2 in [4, 7].
const std::vector<RayHit> kThreeBalls = {hit(2, F, 0), hit(3, F, 1), hit(4, F, 2),
                                         hit(5, B, 1), hit(7, B, 2), hit(10, B, 0)};

} // namespace

class TestInspectWalk : public QObject {
    Q_OBJECT
private slots:
    void csgOfTwoBalls_data();
    void csgOfTwoBalls();
    void csgTreeOfThree_data();
    void csgTreeOfThree();
    void csgOfSelfCrossingOperand();
    void capping_data();
    void capping();
    void cappingNeedsAPlaneStart();
    void collisionFlags();
    void coplanarTies();
    void staticWalkUnchangedWithoutInspection();
};

void TestInspectWalk::csgOfTwoBalls_data()
{
    QTest::addColumn<QString>("expression");
    QTest::addColumn<int>("shown");
    // From outside (near plane): bits (A,B) along the ray: 00 |2| 10 |4| 11 |6| 01 |8| 00.
    // Union: in from 2 on: the F of A at 2 (index 0).
    QTest::newRow("union") << "0 | 1" << 0;
    // Intersection: in only where 11, from 4: the F of B (index 1).
    QTest::newRow("intersection") << "0 & 1" << 1;
    // A - B: in on [2, 4): the F of A (index 0) is first.
    QTest::newRow("A-B") << "0 - 1" << 0;
    // B - A: in on [6, 8): the B of A at 6 (index 2) — the inside of A seen as B's cap.
    QTest::newRow("B-A") << "1 - 0" << 2;
}

void TestInspectWalk::csgOfTwoBalls()
{
    QFETCH(QString, expression);
    QFETCH(int, shown);
    const TrimWalk w = walkTrimRay(kTwoBalls, fromNear(), csg(qPrintable(expression)));
    QCOMPARE(w.windingAtStart, 0);
    QCOMPARE(int(w.shownIndex), shown);
    QCOMPARE(w.capPlane, -1);
}

void TestInspectWalk::csgTreeOfThree_data()
{
    QTest::addColumn<QString>("expression");
    QTest::addColumn<double>("tStart");
    QTest::addColumn<int>("shown");
    // Bits (0,1,2) along the ray: 000 |2| 100 |3| 110 |4| 111 |5| 101 |7| 100 |10| 000.
    // 0 - (1 | 2): in on [2,3), out [3,7), in [7,10): from the near plane the F at 2.
    QTest::newRow("0-(1|2) near") << "0 - (1 | 2)" << 0.1 << 0;
    // ... from a plane at t = 3.5 (inside 0 and 1, out of the result): in again at the
    // B of 2 at 7 (index 4).
    QTest::newRow("0-(1|2) inside") << "0 - (1 | 2)" << 3.5 << 4;
    // (0 & 1) | 2: in on [3, 7): from near, the F of 1 at 3 (index 1).
    QTest::newRow("(0&1)|2 near") << "(0 & 1) | 2" << 0.1 << 1;
    // 0 & 1 & 2: in on [4, 5) only: the F of 2 at 4 (index 2).
    QTest::newRow("0&1&2") << "0 & 1 & 2" << 0.1 << 2;
    // 0 - 1 - 2 (= 0 - (1 | 2)) equals the first row.
    QTest::newRow("0-1-2") << "0 - 1 - 2" << 0.1 << 0;
    // 1 - 2: in on [3, 4): from a plane at 4.5 (in 1 and 2: out), 1's B at 5 ends 1: 001
    // stays out; nothing is in behind 4.5: empty.
    QTest::newRow("1-2 behind") << "1 - 2" << 4.5 << -1;
}

void TestInspectWalk::csgTreeOfThree()
{
    QFETCH(QString, expression);
    QFETCH(double, tStart);
    QFETCH(int, shown);
    const KeptSpan span{false, tStart, 100.0, tStart < 1.0};
    QCOMPARE(int(walkTrimRay(kThreeBalls, span, csg(qPrintable(expression))).shownIndex), shown);
}

void TestInspectWalk::csgOfSelfCrossingOperand()
{
    // Object 0 is self-crossing: a sphere [2, 8] with a second sheet [3, 5] inside it
    // (w_0 = 1, 2, 1 along the ray); object 1 a ball [4, 6].
    const std::vector<RayHit> hits = {hit(2, F, 0), hit(3, F, 0), hit(4, F, 1),
                                      hit(5, B, 0), hit(6, B, 1), hit(8, B, 0)};
    // Parity for object 0: in on [2,3) and [5,8) (w_0 = 1), out on [3,5) (w_0 = 2).
    // 0 | 1 under parity: in [2,3), out? [3,4): w_0 = 2 out, 1 out -> out; so the result is
    // in [2,3), out [3,4), in [4,8). From a plane at 3.5 the F of 1 at 4 (index 2) shows.
    TrimSettings parity = csg("0 | 1", StaticRule::Parity);
    QCOMPARE(int(walkTrimRay(hits, atPlane(3.5, 0), parity).shownIndex), 2);
    // Per-object rules: object 0 by positive index (in wherever w_0 >= 1), 1 by parity.
    // Then 0 | 1 is in on all of [2, 8): from a plane at 3.5 the first boundary is the B
    // of 0 at 8 (index 5).
    TrimSettings mixed = parity;
    mixed.csg.objectRules[0] = StaticRule::PositiveIndex;
    QCOMPARE(int(walkTrimRay(hits, atPlane(3.5, 0), mixed).shownIndex), 5);
    // Without CSG the scene is one surface (sum w = 0 + 1 + 1 + 2 + 1 + 0 ...): positive
    // index from the plane at 3.5: w = 2 (B at 5, 6, 8 minus F at 4) in; 3, 2, 1 in, 0 at 8.
    TrimSettings single;
    single.rule = StaticRule::PositiveIndex;
    const TrimWalk plain = walkTrimRay(hits, atPlane(3.5, 0), single);
    QCOMPARE(plain.windingAtStart, 2);
    QCOMPARE(int(plain.shownIndex), 5);
}

void TestInspectWalk::capping_data()
{
    QTest::addColumn<TrimSettings>("settings");
    QTest::addColumn<double>("tStart");
    QTest::addColumn<int>("cap");
    QTest::addColumn<int>("shown");
    // kTwoBalls as one surface under positive index, a plane at t = 3 (plane 4 of the
    // set): w = -1 (F at 4) + 1 + 1 = 1, in: the cap of plane 4, nothing behind it shown.
    TrimSettings ball;
    ball.rule = StaticRule::PositiveIndex;
    QTest::newRow("positive/inside") << capped(ball) << 3.0 << 4 << -1;
    // A plane at 9, beyond both balls: w = 0, out: no cap, nothing shown.
    QTest::newRow("positive/beyond") << capped(ball) << 9.0 << -1 << -1;
    // Without capping the cut at 3 walks 1 -> 2 -> 1 -> 0: the B of object 1 at 8 (index 3).
    QTest::newRow("positive/uncapped") << ball << 3.0 << -1 << 3;
    // Two balls as one surface under the alternating border rule: a plane at 5 has w = 2
    // (in, 2 mod 4), capped.
    TrimSettings alternating;
    alternating.rule = StaticRule::AlternatingBorder;
    QTest::newRow("two/alternating w=2") << capped(alternating) << 5.0 << 4 << -1;
    // Parity: w = 2 is out: no cap; 2 -> 1 at the B at 6 (index 2) is the trim.
    TrimSettings parity;
    parity.rule = StaticRule::Parity;
    QTest::newRow("two/parity w=2") << capped(parity) << 5.0 << -1 << 2;
    // CSG: B - A from a plane at 5 (in both: out of B - A): no cap, the B of A at 6.
    QTest::newRow("csg/B-A out") << capped(csg("1 - 0")) << 5.0 << -1 << 2;
    // ... from a plane at 7 (in B only: in B - A): the cap.
    QTest::newRow("csg/B-A in") << capped(csg("1 - 0")) << 7.0 << 4 << -1;
    // A & B from a plane at 3 (in A only): no cap; the F of B at 4 (index 1) is the trim.
    QTest::newRow("csg/A&B out") << capped(csg("0 & 1")) << 3.0 << -1 << 1;
}

void TestInspectWalk::capping()
{
    QFETCH(TrimSettings, settings);
    QFETCH(double, tStart);
    QFETCH(int, cap);
    QFETCH(int, shown);
    const std::vector<RayHit>& hits = kTwoBalls;
    const TrimWalk w = walkTrimRay(hits, atPlane(tStart, 4), settings);
    QCOMPARE(w.capPlane, cap);
    QCOMPARE(int(w.shownIndex), shown);
    const TrimPixel pixel = trimPixelFromWalk(hits, w);
    QCOMPARE(int(pixel.capPlane), cap);
    QCOMPARE(pixel.covered(), cap >= 0 || shown >= 0);
    if (cap >= 0) {
        QCOMPARE(pixel.viewDepth, float(tStart));
        QCOMPARE(pixel.primitiveId, -1);
        QCOMPARE(pixel.objectId, -1);
        QCOMPARE(int(pixel.facing), 0);
    }
}

void TestInspectWalk::cappingNeedsAPlaneStart()
{
    // The eye inside the ball (span from the near plane, w = 1): no cap at the near plane.
    const std::vector<RayHit> inside = {hit(3, B)};
    TrimSettings s = capped(TrimSettings{});
    const TrimWalk w = walkTrimRay(inside, fromNear(), s);
    QCOMPARE(w.capPlane, -1);
    QCOMPARE(int(w.shownIndex), 0);
    // Trimming off: no interior, no cap (the first hit in the span shows).
    s.trimEnabled = false;
    QCOMPARE(walkTrimRay(kTwoBalls, atPlane(3.0, 1), s).capPlane, -1);
    // Capping off: no cap.
    s.trimEnabled = true;
    s.cap.enabled = false;
    QCOMPARE(walkTrimRay(kTwoBalls, atPlane(3.0, 1), s).capPlane, -1);
}

void TestInspectWalk::collisionFlags()
{
    TrimSettings s;
    s.rule = StaticRule::PositiveIndex;
    s.highlight.collisions = true;
    // Two balls, positive index as one surface, from a plane at 5 (w = 2): the first
    // boundary is A's B at 6 (2 -> 1? no: 2 and 1 are both in) ... 1 -> 0 at B's B at 8.
    // That B of object 1 lies outside object 0 (w_0 = 0 behind 6) and w_1 goes 1 -> 0:
    // no collision.
    TrimWalk w = walkTrimRay(kTwoBalls, atPlane(5.0, 0), s);
    QCOMPARE(int(w.shownIndex), 3);
    QVERIFY(!w.collision);
    // Parity: 2 -> 1 at A's B at 6: it lies inside object 1 (w_1 = 1 there): collision.
    s.rule = StaticRule::Parity;
    w = walkTrimRay(kTwoBalls, atPlane(5.0, 0), s);
    QCOMPARE(int(w.shownIndex), 2);
    QVERIFY(w.collision);
    QVERIFY(trimPixelFromWalk(kTwoBalls, w).collision);
    // From outside, A's F at 2 lies in nothing else: no collision.
    w = walkTrimRay(kTwoBalls, fromNear(), s);
    QCOMPARE(int(w.shownIndex), 0);
    QVERIFY(!w.collision);
    // Self-collision: one object with two nested sheets (w_0: 1 -> 2 at the inner F).
    // Parity from a plane at 2.5 (w = 1): 1 -> 2 at the inner F at 3 is a boundary and
    // its far side has |w_0| = 2: the object overlaps itself there.
    const std::vector<RayHit> doubled = {hit(2, F), hit(3, F), hit(4, B), hit(5, B)};
    w = walkTrimRay(doubled, atPlane(2.5, 0), s);
    QCOMPARE(int(w.shownIndex), 1);
    QVERIFY(w.collision);
    // The highlight off: never flagged.
    s.highlight.collisions = false;
    QVERIFY(!walkTrimRay(doubled, atPlane(2.5, 0), s).collision);
}

void TestInspectWalk::coplanarTies()
{
    // A sphere duplicated on itself (objects 0 and 1 at equal t), sorted in walk order.
    const std::vector<RayHit> doubled = {hit(2, F, 0, 5), hit(2, F, 1, 5), hit(4, B, 0, 6), hit(4, B, 1, 6)};
    TrimSettings s;
    s.rule = StaticRule::AlternatingBorder;
    s.highlight.coplanar = true;
    // From outside: object 0's F at 2 (first in walk order) with a group of 2.
    TrimWalk w = walkTrimRay(doubled, fromNear(), s);
    QCOMPARE(int(w.shownIndex), 0);
    QCOMPARE(w.coplanarCount, 2);
    TrimPixel p = trimPixelFromWalk(doubled, w);
    QCOMPARE(p.objectId, 0);
    QCOMPARE(int(p.coplanarCount), 2);
    // A plane at 3 (w = 2): alternating 2 -> 1 at object 0's B is not a boundary, 1 -> 0
    // at object 1's B is: the shown fragment is the second of the tied pair, group of 2.
    w = walkTrimRay(doubled, atPlane(3.0, 0), s);
    QCOMPARE(int(w.shownIndex), 3);
    QCOMPARE(w.coplanarCount, 2);
    // A single sheet: group of 1. The highlight off: 0.
    const std::vector<RayHit> single = {hit(2, F), hit(4, B)};
    QCOMPARE(walkTrimRay(single, fromNear(), s).coplanarCount, 1);
    s.highlight.coplanar = false;
    QCOMPARE(walkTrimRay(doubled, fromNear(), s).coplanarCount, 0);
    // Three sheets tie, the shown one first: all three counted (those after it too).
    const std::vector<RayHit> triple = {hit(2, F, 0), hit(2, F, 1), hit(2, F, 2),
                                        hit(4, B, 0), hit(4, B, 1), hit(4, B, 2)};
    s.highlight.coplanar = true;
    QCOMPARE(walkTrimRay(triple, fromNear(), s).coplanarCount, 3);
}

void TestInspectWalk::staticWalkUnchangedWithoutInspection()
{
    // The same decisions as tst_trim_walk's table for a few of its rows, with every
    // inspection field at its neutral value.
    TrimSettings s;
    const std::vector<RayHit> nested = {hit(2, F, 0), hit(3, F, 1), hit(4, B, 1), hit(5, B, 0)};
    const TrimWalk w = walkTrimRay(nested, atPlane(3.5, 0), s);
    QCOMPARE(w.windingAtStart, 2);
    QCOMPARE(int(w.shownIndex), 3);
    QCOMPARE(w.capPlane, -1);
    QVERIFY(!w.collision);
    QCOMPARE(w.coplanarCount, 0);
    // Capping enabled but no plane enabled: capping() is false, the static walk runs.
    s.cap.enabled = true;
    QVERIFY(!s.capping());
    QCOMPARE(int(walkTrimRay(nested, atPlane(3.5, 0), s).shownIndex), 3);
}

QTEST_APPLESS_MAIN(TestInspectWalk)
#include "tst_inspect_walk.moc"
