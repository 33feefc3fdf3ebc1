// walkTrimRay on hand-written hit lists whose answers are derived by hand in the comments.
// Notation: F = front-facing (enters, w+1), B = back-facing (exits, w-1); w(tStart) is
// counted from the far side: +1 for every B beyond tStart, -1 for every F.
#include "core/trim/trim_walk.h"

#include <QtTest>

#include <vector>

using namespace trimlab;

Q_DECLARE_METATYPE(std::vector<trimlab::RayHit>)
Q_DECLARE_METATYPE(trimlab::KeptSpan)

namespace {

constexpr int F = 1;
constexpr int B = -1;
constexpr int kNone = -1;

RayHit hit(double t, int facing, int objectId = 0, int primitiveId = 0)
{
    return {t, objectId, primitiveId, facing, 0.25, 0.5};
}

KeptSpan fromNear(double tEnd = 100.0)
{
    return {false, 0.1, tEnd, true};
}

KeptSpan fromPlane(double tStart, double tEnd = 100.0)
{
    return {false, tStart, tEnd, false};
}

TrimSettings rule(StaticRule r)
{
    TrimSettings s;
    s.rule = r;
    return s;
}

TrimSettings untrimmed()
{
    TrimSettings s;
    s.trimEnabled = false;
    return s;
}

} // namespace

class TestTrimWalk : public QObject {
    Q_OBJECT
private slots:
    void walk_data();
    void walk();
    void pixelFields();
    void emptySpanShowsNothing();
};

void TestTrimWalk::walk_data()
{
    QTest::addColumn<std::vector<RayHit>>("hits");
    QTest::addColumn<KeptSpan>("span");
    QTest::addColumn<TrimSettings>("settings");
    QTest::addColumn<int>("winding");
    QTest::addColumn<int>("shown");
    using R = StaticRule;
    const std::vector<RayHit> sphere = {hit(2, F), hit(4, B)};
    // Outside a sphere, w = -1 + 1 = 0; F takes 0 -> 1, a boundary under every rule.
    QTest::newRow("sphere/alternating") << sphere << fromNear() << rule(R::AlternatingBorder) << 0 << 0;
    QTest::newRow("sphere/parity") << sphere << fromNear() << rule(R::Parity) << 0 << 0;
    QTest::newRow("sphere/positive") << sphere << fromNear() << rule(R::PositiveIndex) << 0 << 0;
    QTest::newRow("sphere/untrimmed") << sphere << fromNear() << untrimmed() << 0 << 0;
    // Clip plane at t = 3 inside the sphere, keeping the far side: w = +1 (the B at 4);
    // B takes 1 -> 0: shown under every rule.
    QTest::newRow("sphere/plane-inside") << sphere << fromPlane(3) << rule(R::AlternatingBorder) << 1 << 1;
    // Plane beyond the sphere: nothing left, w = 0.
    QTest::newRow("sphere/plane-behind") << sphere << fromPlane(5) << rule(R::AlternatingBorder) << 0 << kNone;
    // Keeping the near side up to t = 3: w(near) = 0, F at 2 is shown.
    QTest::newRow("sphere/near-half") << sphere << fromNear(3) << rule(R::Parity) << 0 << 0;
    // Keeping the near side up to t = 1.5: the F at 2 is clipped, nothing shown.
    QTest::newRow("sphere/near-half-before") << sphere << fromNear(1.5) << rule(R::Parity) << 0 << kNone;

    // Nested outward spheres (outer 2..5, inner 3..4), plane at 3.5 keeping the far side:
    // w = +1 +1 = 2; inner B: 2 -> 1, outer B: 1 -> 0.
    const std::vector<RayHit> nested = {hit(2, F, 0), hit(3, F, 1), hit(4, B, 1), hit(5, B, 0)};
    // alternating: 2 and 1 both in, 1 -> 0 is the boundary: the outer back face.
    QTest::newRow("nested/alternating") << nested << fromPlane(3.5) << rule(R::AlternatingBorder) << 2 << 3;
    // parity: 2 out, 1 in: the inner back face.
    QTest::newRow("nested/parity") << nested << fromPlane(3.5) << rule(R::Parity) << 2 << 2;
    // positive: 2, 1 in, 0 out: the outer back face.
    QTest::newRow("nested/positive") << nested << fromPlane(3.5) << rule(R::PositiveIndex) << 2 << 3;
    QTest::newRow("nested/untrimmed") << nested << fromPlane(3.5) << untrimmed() << 2 << 2;
    // From the near plane: w = 0, outer F 0 -> 1 shown by every rule.
    QTest::newRow("nested/near") << nested << fromNear() << rule(R::Parity) << 0 << 0;

    // A span starting inside w = 1 whose kept part only sees 1 -> 2 -> 1 (tEnd = 5 cuts
    // off the last B at 7): w = -1 + 1 + 1 = 1.
    const std::vector<RayHit> bump = {hit(2, F), hit(3, B), hit(7, B)};
    // alternating: 1, 2 both in -> nothing in the span.
    QTest::newRow("bump/alternating") << bump << fromPlane(1, 5) << rule(R::AlternatingBorder) << 1 << kNone;
    // positive: 1, 2 both in -> nothing.
    QTest::newRow("bump/positive") << bump << fromPlane(1, 5) << rule(R::PositiveIndex) << 1 << kNone;
    // parity: 1 in, 2 out -> the F at 2.
    QTest::newRow("bump/parity") << bump << fromPlane(1, 5) << rule(R::Parity) << 1 << 0;
    // With tEnd = 7 (inclusive) the last B (1 -> 0) is shown under alternating.
    QTest::newRow("bump/tEnd-inclusive") << bump << fromPlane(1, 7) << rule(R::AlternatingBorder) << 1 << 2;

    // An inward-oriented sphere seen from outside: B then F; w = +1 - 1 = 0.
    const std::vector<RayHit> inward = {hit(2, B), hit(4, F)};
    // 0 -> -1: alternating (-1 mod 4 = 3: out) and positive see no boundary; parity does.
    QTest::newRow("inward/alternating") << inward << fromNear() << rule(R::AlternatingBorder) << 0 << kNone;
    QTest::newRow("inward/positive") << inward << fromNear() << rule(R::PositiveIndex) << 0 << kNone;
    QTest::newRow("inward/parity") << inward << fromNear() << rule(R::Parity) << 0 << 0;

    // Camera inside a sphere: only the far B remains, w = 1, 1 -> 0 shown.
    QTest::newRow("inside") << std::vector<RayHit>{hit(1, B)} << fromNear() << rule(R::AlternatingBorder) << 1 << 0;

    // A hit exactly at tStart is in front of the span: not counted, not shown. w = +1.
    const std::vector<RayHit> onPlane = {hit(3, F), hit(5, B)};
    QTest::newRow("hit-at-tStart") << onPlane << fromPlane(3) << rule(R::Parity) << 1 << 1;

    // The same sphere twice (objects 0 and 1), equal t; walk order: object 0 first.
    // Plane at 3: w = 2; B(o0): 2 -> 1, B(o1): 1 -> 0.
    const std::vector<RayHit> doubled = {hit(2, F, 0), hit(2, F, 1), hit(4, B, 0), hit(4, B, 1)};
    QTest::newRow("doubled/alternating") << doubled << fromPlane(3) << rule(R::AlternatingBorder) << 2 << 3;
    QTest::newRow("doubled/parity") << doubled << fromPlane(3) << rule(R::Parity) << 2 << 2;
    // From outside: w = 0, F(o0): 0 -> 1 is a boundary for every rule.
    QTest::newRow("doubled/outside") << doubled << fromNear() << rule(R::AlternatingBorder) << 0 << 0;

    // Four nested outward shells: F@1 F@2 F@2.2 F@3 B@4 B@5 B@6 B@7. A plane at 2.5
    // (inside three shells): beyond it one F and four B, w = 4 - 1 = 3.
    const std::vector<RayHit> shells = {hit(1, F), hit(2, F), hit(2.2, F), hit(3, F),
                                        hit(4, B), hit(5, B), hit(6, B),   hit(7, B)};
    // alternating: 3 out -> 4 out (no), 4 -> 3 (no), 3 out -> 2 in: the B at 5.
    QTest::newRow("shells/alternating") << shells << fromPlane(2.5) << rule(R::AlternatingBorder) << 3 << 5;
    // parity: 3 in -> 4 out: the F at 3.
    QTest::newRow("shells/parity") << shells << fromPlane(2.5) << rule(R::Parity) << 3 << 3;
    // positive: 3, 4, 3, 2, 1 in; 1 -> 0 at the B at 7.
    QTest::newRow("shells/positive") << shells << fromPlane(2.5) << rule(R::PositiveIndex) << 3 << 7;
}

void TestTrimWalk::walk()
{
    QFETCH(std::vector<RayHit>, hits);
    QFETCH(KeptSpan, span);
    QFETCH(TrimSettings, settings);
    QFETCH(int, winding);
    QFETCH(int, shown);
    const TrimWalk w = walkTrimRay(hits, span, settings);
    QCOMPARE(w.windingAtStart, winding);
    QCOMPARE(int(w.shownIndex), shown);
    const TrimPixel pixel = resolveTrimPixel(hits, span, settings);
    QCOMPARE(pixel.windingAtStart, winding);
    QCOMPARE(pixel.covered(), shown >= 0);
}

void TestTrimWalk::pixelFields()
{
    const std::vector<RayHit> hits = {hit(2.5, F, 3, 17), hit(4.0, B, 1, 9)};
    const TrimPixel front = resolveTrimPixel(hits, fromNear(), TrimSettings{});
    QCOMPARE(front.viewDepth, 2.5f);
    QCOMPARE(front.objectId, 3);
    QCOMPARE(front.primitiveId, 17);
    QCOMPARE(int(front.facing), 1);
    QCOMPARE(front.windingAtStart, 0);
    const TrimPixel back = resolveTrimPixel(hits, fromPlane(3.0), TrimSettings{});
    QCOMPARE(back.viewDepth, 4.0f);
    QCOMPARE(back.objectId, 1);
    QCOMPARE(back.primitiveId, 9);
    QCOMPARE(int(back.facing), -1);
    QCOMPARE(back.windingAtStart, 1);
    // Empty pixel with a non-empty span keeps its winding index.
    const TrimPixel none = resolveTrimPixel(hits, fromPlane(3.0, 3.5), TrimSettings{});
    QVERIFY(!none.covered());
    QCOMPARE(none.primitiveId, -1);
    QCOMPARE(int(none.facing), 0);
    QVERIFY(std::isinf(none.viewDepth));
    QCOMPARE(none.windingAtStart, 1);
}

void TestTrimWalk::emptySpanShowsNothing()
{
    const std::vector<RayHit> hits = {hit(2, F), hit(4, B)};
    const KeptSpan empty{true, 0.0, 0.0, true};
    const TrimWalk w = walkTrimRay(hits, empty, TrimSettings{});
    QCOMPARE(w.windingAtStart, 0);
    QCOMPARE(int(w.shownIndex), -1);
    QVERIFY(!resolveTrimPixel(hits, empty, TrimSettings{}).covered());
    // No hits at all.
    QCOMPARE(walkTrimRay({}, fromNear(), TrimSettings{}).windingAtStart, 0);
}

QTEST_APPLESS_MAIN(TestTrimWalk)
#include "tst_trim_walk.moc"
