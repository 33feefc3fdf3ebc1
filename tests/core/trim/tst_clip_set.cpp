// Clipping with several planes at once: the kept span of a ClipSet on rays whose answers
// are derived by hand (a box, disjoint half-spaces), and bit-identity with the one-plane
// keptSpan that every existing test and renderer relies on.
#include "core/trim/clip_set.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <random>

using namespace trimlab;

namespace {

// A ray from (0, 0, 10) along -z: t is the distance travelled, view depth.
const PixelRay kDown{{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};

} // namespace

class TestClipSet : public QObject {
    Q_OBJECT
private slots:
    void onePlaneMatchesKeptSpanBitForBit();
    void boxKeepsItsInterval();
    void rayStartingInsideTheBox();
    void disjointPlanesKeepNothing();
    void boxMissedByTheRay();
    void runnerUpPlanes();
    void keepsAndCounts();
    void parsesRepeatedClipOptions();
};

void TestClipSet::onePlaneMatchesKeptSpanBitForBit()
{
    std::mt19937 random(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const PixelRay ray{{3 * u(random), 3 * u(random), 3 * u(random)}, {u(random), u(random), u(random)}};
        const ClipPlane plane{true, {u(random), u(random), u(random)}, u(random)};
        for (int slot : {0, 3}) {
            ClipSet set;
            set.planes[std::size_t(slot)] = plane;
            const KeptSpan a = keptSpan(plane, ray, 0.1, 10.0);
            const KeptSpan b = keptSpan(set, ray, 0.1, 10.0);
            QCOMPARE(b.empty, a.empty);
            if (a.empty)
                continue;
            QCOMPARE(b.tStart, a.tStart); // exact: the same arithmetic
            QCOMPARE(b.tEnd, a.tEnd);
            QCOMPARE(b.startsAtNear, a.startsAtNear);
            QCOMPARE(b.startPlane, a.startsAtNear ? -1 : slot);
        }
    }
    // A disabled set keeps [zNear, zFar].
    const KeptSpan all = keptSpan(ClipSet{}, kDown, 0.5, 20.0);
    QVERIFY(!all.empty && all.startsAtNear);
    QCOMPARE(all.tStart, 0.5);
    QCOMPARE(all.tEnd, 20.0);
    QCOMPARE(all.startPlane, -1);
    QCOMPARE(all.endPlane, -1);
}

void TestClipSet::boxKeepsItsInterval()
{
    // Box [-1,1]×[-2,2]×[-3,3]: the ray down the z axis enters at z = 3 (t = 7, plane 5:
    // z <= 3) and leaves at z = -3 (t = 13, plane 4: z >= -3).
    const ClipSet box = ClipSet::box({-1.0, -2.0, -3.0}, {1.0, 2.0, 3.0});
    QCOMPARE(box.enabledCount(), 6);
    const KeptSpan s = keptSpan(box, kDown, 0.1, 100.0);
    QVERIFY(!s.empty);
    QCOMPARE(s.tStart, 7.0);
    QCOMPARE(s.tEnd, 13.0);
    QVERIFY(!s.startsAtNear);
    QCOMPARE(s.startPlane, 5);
    QCOMPARE(s.endPlane, 4);
    // A far plane before the box's back keeps [7, 11].
    const KeptSpan shortened = keptSpan(box, kDown, 0.1, 11.0);
    QCOMPARE(shortened.tEnd, 11.0);
    QCOMPARE(shortened.endPlane, -1);
}

void TestClipSet::rayStartingInsideTheBox()
{
    // The eye at the origin inside the box, looking along +x: span from the near plane to
    // x = 1 (t = 1, plane 1: x <= 1).
    const ClipSet box = ClipSet::box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    const KeptSpan s = keptSpan(box, PixelRay{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, 0.01, 50.0);
    QVERIFY(!s.empty && s.startsAtNear);
    QCOMPARE(s.tStart, 0.01);
    QCOMPARE(s.tEnd, 1.0);
    QCOMPARE(s.startPlane, -1);
    QCOMPARE(s.endPlane, 1);
}

void TestClipSet::disjointPlanesKeepNothing()
{
    // x >= 1 and x <= -1 together keep nothing: every ray's span is empty, also rays that
    // cross both planes (the intervals [t1, far] and [near, t2] do not meet).
    ClipSet set;
    set.planes[0] = ClipPlane{true, {1.0, 0.0, 0.0}, -1.0};
    set.planes[2] = ClipPlane{true, {-1.0, 0.0, 0.0}, -1.0};
    const PixelRay across{{-5.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
    QVERIFY(keptSpan(set, across, 0.1, 100.0).empty);
    QVERIFY(keptSpan(set, PixelRay{{5.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}}, 0.1, 100.0).empty);
    QVERIFY(keptSpan(set, kDown, 0.1, 100.0).empty); // parallel to both, kept by neither at x = 0
    // A box with lower > upper on one axis is the same.
    QVERIFY(keptSpan(ClipSet::box({0.0, -1.0, -1.0}, {-0.5, 1.0, 1.0}), across, 0.1, 100.0).empty);
}

void TestClipSet::boxMissedByTheRay()
{
    // The ray x = 5 passes beside the box: plane 1 (x <= 1) keeps none of it.
    const ClipSet box = ClipSet::box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    QVERIFY(keptSpan(box, PixelRay{{5.0, 0.0, 10.0}, {0.0, 0.0, -1.0}}, 0.1, 100.0).empty);
    // A diagonal ray in the plane z = 0, from (−2, 3, 0) along (1, −1, 0): it enters
    // x >= −1 at t = 1 and y <= 1 at t = 2, leaves x <= 1 at t = 3 and y >= −1 at t = 4:
    // kept [2, 3], starting at plane 3 (y <= 1), ending at plane 1 (x <= 1).
    const KeptSpan diagonal = keptSpan(box, PixelRay{{-2.0, 3.0, 0.0}, {1.0, -1.0, 0.0}}, 0.1, 100.0);
    QVERIFY(!diagonal.empty);
    QCOMPARE(diagonal.tStart, 2.0);
    QCOMPARE(diagonal.startPlane, 3);
    QCOMPARE(diagonal.tEnd, 3.0);
    QCOMPARE(diagonal.endPlane, 1);
    // Moved up by 3: it enters y <= 1 only at t = 5, after leaving x <= 1 at t = 3: empty.
    QVERIFY(keptSpan(box, PixelRay{{-2.0, 6.0, 0.0}, {1.0, -1.0, 0.0}}, 0.1, 100.0).empty);
}

void TestClipSet::runnerUpPlanes()
{
    // The diagonal ray above: lower bounds x >= -1 at t = 1 and y <= 1 at t = 2; upper
    // bounds x <= 1 at t = 3 and y >= -1 at t = 4.
    const ClipSet box = ClipSet::box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    const KeptSpan s = keptSpan(box, PixelRay{{-2.0, 3.0, 0.0}, {1.0, -1.0, 0.0}}, 0.1, 100.0);
    QCOMPARE(s.startRunnerUp, 1.0);
    QCOMPARE(s.endRunnerUp, 4.0);
    // One plane: no runner-up.
    const KeptSpan one = keptSpan(ClipSet::single(ClipPlane{true, {0.0, 0.0, -1.0}, 0.0}), kDown, 0.1, 100.0);
    QVERIFY(std::isinf(one.startRunnerUp) && one.startRunnerUp < 0);
    QVERIFY(std::isinf(one.endRunnerUp) && one.endRunnerUp > 0);
}

void TestClipSet::keepsAndCounts()
{
    const ClipSet box = ClipSet::box({-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0});
    QVERIFY(box.keeps({0.0, 0.0, 0.0}));
    QVERIFY(box.keeps({1.0, -1.0, 1.0})); // the boundary is kept (n·x + d >= 0)
    QVERIFY(!box.keeps({1.001, 0.0, 0.0}));
    ClipSet partial = box;
    partial.planes[1].enabled = false; // x <= 1 off
    QCOMPARE(partial.enabledCount(), 5);
    QVERIFY(partial.keeps({50.0, 0.0, 0.0}));
    QVERIFY(ClipSet{}.keeps({1e9, -1e9, 0.0}));
    QVERIFY(!ClipSet{}.anyEnabled());
}

void TestClipSet::parsesRepeatedClipOptions()
{
    std::string error;
    const auto set = parseClipSet({"1,0,0,1", "0,-1,0,2"}, &error);
    QVERIFY2(set, error.c_str());
    QCOMPARE(set->enabledCount(), 2);
    QCOMPARE(set->planes[1].normal, glm::dvec3(0.0, -1.0, 0.0));
    QCOMPARE(set->planes[1].offset, 2.0);
    QVERIFY(!set->planes[2].enabled);
    QVERIFY(!parseClipSet({"1,0,0,1", "0,0,0,1"}, &error));
    QVERIFY2(error.find("plane 2") != std::string::npos && error.find("zero") != std::string::npos, error.c_str());
    QVERIFY(!parseClipSet(std::vector<std::string>(7, "1,0,0,0"), &error));
    QVERIFY2(error.find("at most 6") != std::string::npos, error.c_str());
    QVERIFY(!parseClipSet({"1,2,3"}, &error));
    QVERIFY2(error.find("plane 1") != std::string::npos, error.c_str());
    QCOMPARE(parseClipSet({}, &error)->enabledCount(), 0);
}

QTEST_APPLESS_MAIN(TestClipSet)
#include "tst_clip_set.moc"
