// The skeleton evaluator (core/skeleton/skeleton_evaluation.h) on shapes whose answers are
// known by construction: a capsule's axis (inside, centred, covering every vertex at the
// radius), the same axis moved off centre or out of the solid, a torus's core circle (one
// cycle, genus 1), and the fast winding number it classifies with against the exact
// solid-angle sum (trim/winding_number.h).
#include "core/skeleton/skeleton_evaluation.h"

#include "core/scene/scene.h"
#include "core/scene/shape_generators.h"
#include "core/trim/fast_winding_number.h"
#include "core/trim/winding_number.h"

#include "skeleton_shapes.h"

#include <QtTest>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace trimlab;
using namespace trimlab::test;

namespace {

constexpr double kRadius = 0.3;
constexpr double kHalfLength = 1.0;

TriangleMesh capsule()
{
    return axisCapsule(kRadius, kHalfLength, 8, 24, 32);
}

SkeletonGraph segment(const glm::dvec3& a, const glm::dvec3& b)
{
    return {{a, b}, {{0, 1}}};
}

Scene sceneOf(const TriangleMesh& mesh)
{
    Scene scene;
    scene.objects.push_back(SceneObject{"mesh", mesh, glm::dmat4(1.0)});
    return scene;
}

} // namespace

class TestSkeletonEvaluation : public QObject {
    Q_OBJECT

private slots:
    void theAxisOfACapsuleIsInsideCentredAndCovering()
    {
        const TriangleMesh mesh = capsule();
        const SkeletonEvaluator evaluator(mesh);
        const SkeletonEvaluation e = evaluator.evaluate(segment({0, -kHalfLength, 0}, {0, kHalfLength, 0}));
        const double diagonal = e.diagonal;
        QVERIFY(diagonal > 2.0 * kHalfLength);
        QCOMPARE(e.nodesInside, 1.0);
        QCOMPARE(e.samplesInside, 1.0);
        QCOMPARE(e.lengthOutside, 0.0);
        QCOMPARE(e.edgesLeaving, 0);
        QCOMPARE(e.samples, int(std::ceil(2.0 * kHalfLength / (0.005 * diagonal)))); // the default spacing
        QVERIFY2(e.meanAsymmetry < 0.02, qPrintable(QString::number(e.meanAsymmetry)));
        QVERIFY2(e.meanWallAsymmetry < 0.02, qPrintable(QString::number(e.meanWallAsymmetry)));
        // Every vertex lies at the radius from the axis segment (the caps' too: the
        // segment ends where they begin).
        QVERIFY(std::abs(e.maxCoverage * diagonal - kRadius) < 1e-6);
        QVERIFY(e.meanCoverage * diagonal > 0.99 * kRadius);
        QCOMPARE(e.components, 1);
        QCOMPARE(e.cycles, 0);
        QCOMPARE(e.meshComponents, 1);
        QCOMPARE(e.meshGenus, 0);
        QVERIFY(std::abs(e.length * diagonal - 2.0 * kHalfLength) < 1e-9);
    }

    // Half a radius off the axis: the nearest-wall pair reads the offset (r/2 from a wall
    // at r/2 and one at 3r/2: asymmetry ½); the shortest chord through the point is bisected
    // by it and cannot (see the header), and coverage grows by the offset.
    void anOffCentreAxisIsSeenByTheNearestWallPair()
    {
        const TriangleMesh mesh = capsule();
        const SkeletonEvaluator evaluator(mesh);
        const double offset = 0.5 * kRadius;
        const SkeletonEvaluation e = evaluator.evaluate(segment({offset, -0.8, 0}, {offset, 0.8, 0}));
        QCOMPARE(e.samplesInside, 1.0);
        QVERIFY2(std::abs(e.meanWallAsymmetry - 0.5) < 0.05, qPrintable(QString::number(e.meanWallAsymmetry)));
        QVERIFY2(e.meanAsymmetry < 0.1, qPrintable(QString::number(e.meanAsymmetry)));
        QVERIFY(e.maxCoverage * e.diagonal > kRadius + 0.9 * offset);
    }

    // A bone from the centre out through the side: the part beyond the radius is outside.
    void aBoneLeavingTheSolidIsMeasured()
    {
        const TriangleMesh mesh = capsule();
        const SkeletonEvaluator evaluator(mesh);
        const SkeletonEvaluation e = evaluator.evaluate(segment({0, 0, 0}, {4.0 * kRadius, 0, 0}));
        QCOMPARE(e.nodesInside, 0.5);
        QCOMPARE(e.edgesLeaving, 1);
        // The polygon of 32 sides is inscribed in the circle: its wall is within 0.5 % of r.
        QVERIFY2(std::abs(e.lengthOutside - 0.75) < 0.02, qPrintable(QString::number(e.lengthOutside)));
        QVERIFY(std::abs(e.samplesInside - 0.25) < 0.02);
    }

    void theCoreCircleOfATorusIsOneCycle()
    {
        const double major = 1.0;
        const double minor = 0.25;
        const TriangleMesh torus = makeTorus({0, 0, 0}, major, minor, 48, 16);
        SkeletonGraph circle;
        const int n = 24;
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * glm::pi<double>() * i / n;
            circle.nodes.push_back({major * std::cos(a), 0.0, major * std::sin(a)});
            circle.edges.push_back({std::min(i, (i + 1) % n), std::max(i, (i + 1) % n)});
        }
        const SkeletonEvaluation e = SkeletonEvaluator(torus).evaluate(circle);
        QCOMPARE(e.meshGenus, 1);
        QCOMPARE(e.cycles, 1);
        QCOMPARE(e.components, 1);
        QCOMPARE(e.samplesInside, 1.0);
        // The chords of a 24-gon sag inward by 1 − cos(7.5°) = 0.9 % of the major radius.
        QVERIFY2(e.meanWallAsymmetry < 0.06, qPrintable(QString::number(e.meanWallAsymmetry)));

        // Opening the loop (one edge less) loses the cycle; two separate nodes add parts.
        SkeletonGraph open = circle;
        open.edges.pop_back();
        open.nodes.push_back({0, 0, 0});
        const SkeletonEvaluation o = SkeletonEvaluator(torus).evaluate(open);
        QCOMPARE(o.cycles, 0);
        QCOMPARE(o.components, 2);
        QCOMPARE(o.nodesInside, 24.0 / 25.0); // the torus's hole is outside
    }

    void aGraphNamingAMissingNodeIsRefused()
    {
        const SkeletonEvaluator evaluator(capsule());
        SkeletonGraph bad = segment({0, 0, 0}, {0, 0.5, 0});
        bad.edges.push_back({1, 2});
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)evaluator.evaluate(bad));
        SkeletonGraph nan = segment({0, 0, 0}, {0, std::nan(""), 0});
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)evaluator.evaluate(nan));
    }

    // Away from the surface the hierarchy's dipole sums stay within 10⁻² of the exact
    // solid-angle sum and classify like it, for points inside, outside and near the torus.
    void theFastWindingNumberAgreesWithTheExactSum()
    {
        const Scene scene = sceneOf(makeTorus({0, 0, 0}, 1.0, 0.4, 64, 24));
        const FastWindingNumber fast(scene);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
        int insideCount = 0;
        double worst = 0.0;
        for (int i = 0; i < 400; ++i) {
            const glm::dvec3 p(coordinate(random), 0.5 * coordinate(random), coordinate(random));
            // Distance to the torus surface: |distance to the core circle − minor radius|.
            const double ring = std::hypot(std::hypot(p.x, p.z) - 1.0, p.y);
            if (std::abs(ring - 0.4) < 0.02)
                continue; // the polygonal surface is within 0.5 % of the smooth one
            const double exact = solidAngleWindingNumber(scene, p);
            worst = std::max(worst, std::abs(fast.at(p) - exact));
            QVERIFY2(std::abs(fast.at(p) - exact) < 1e-2, qPrintable(QString("%1 vs %2").arg(fast.at(p)).arg(exact)));
            QCOMPARE(fast.inside(p), ring < 0.4);
            insideCount += ring < 0.4 ? 1 : 0;
        }
        qInfo("worst difference %.3g over %d points inside", worst, insideCount);
        QVERIFY(insideCount > 20);
    }
};

QTEST_APPLESS_MAIN(TestSkeletonEvaluation)
#include "tst_skeleton_evaluation.moc"
