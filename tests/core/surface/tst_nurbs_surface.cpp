// NURBS surface evaluation (core/surface/nurbs_surface.h, nurbs_primitives.h): the exact
// rational primitives lie on their analytic surfaces, derivatives match central
// differences, normals are unit and outward (poles included), and the ties between
// seam twins and pole points hold.
#include "core/surface/nurbs_primitives.h"
#include "core/surface/nurbs_surface.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>

using namespace trimlab;

namespace {

const glm::dvec3 kCenter(0.25, -1.5, 3.0);

// A dense grid over the domain, its ends, and every knot line.
template <class F>
void forGrid(const NurbsSurface& s, int n, F&& f)
{
    const ParameterRange ru = parameterRangeU(s), rv = parameterRangeV(s);
    std::vector<double> us, vs;
    for (int k = 0; k <= n; ++k) {
        us.push_back(ru.begin + ru.length() * k / n);
        vs.push_back(rv.begin + rv.length() * k / n);
    }
    us.insert(us.end(), s.knotsU.begin(), s.knotsU.end());
    vs.insert(vs.end(), s.knotsV.begin(), s.knotsV.end());
    for (const double u : us)
        for (const double v : vs)
            f(u, v);
}

QString at(double u, double v)
{
    return QString("(u, v) = (%1, %2)").arg(u, 0, 'g', 17).arg(v, 0, 'g', 17);
}

// Distance from `p` to the axis (y) of a surface of revolution centred at kCenter.
double axisDistance(const glm::dvec3& p)
{
    return std::hypot(p.x - kCenter.x, p.z - kCenter.z);
}

} // namespace

class TestNurbsSurface : public QObject {
    Q_OBJECT

private slots:
    void primitivesAreValid()
    {
        QVERIFY(!findNurbsProblem(makeNurbsSphere(kCenter, 2.0)));
        QVERIFY(!findNurbsProblem(makeNurbsTorus(kCenter, 2.0, 0.5)));
        QVERIFY(!findNurbsProblem(makeNurbsCylinder(kCenter, 1.0, 3.0)));
        QVERIFY(!findNurbsProblem(makeNurbsCappedTube(kCenter, 1.0, 3.0)));
        QVERIFY(!findNurbsProblem(makeNurbsPatch(kCenter, 4.0, 3.0, 7, 5)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeNurbsSphere(kCenter, -1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeNurbsTorus(kCenter, 1.0, 1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeNurbsCappedTube(kCenter, 1.0, std::nan("")));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeNurbsPatch(kCenter, 1.0, 1.0, 3, 5));
    }

    void spherePointsLieOnTheSphere()
    {
        for (const double radius : {1.0, 0.001, 250.0}) {
            const NurbsSurface s = makeNurbsSphere(kCenter, radius);
            double worst = 0.0;
            forGrid(s, 160, [&](double u, double v) {
                const double r = glm::length(evaluateNurbsPoint(s, u, v) - kCenter);
                worst = std::max(worst, std::abs(r - radius) / radius);
            });
            QVERIFY2(worst <= 1e-9, qPrintable(QString("relative radius error %1").arg(worst)));
        }
        // The poles are where the profile says.
        const NurbsSurface s = makeNurbsSphere(kCenter, 2.0);
        QVERIFY(glm::length(evaluateNurbsPoint(s, 1.3, 0.0) - (kCenter + glm::dvec3(0, -2, 0))) <= 1e-14);
        QVERIFY(glm::length(evaluateNurbsPoint(s, 3.7, 2.0) - (kCenter + glm::dvec3(0, 2, 0))) <= 1e-14);
    }

    void torusPointsLieOnTheTorus()
    {
        const double R = 2.0, r = 0.6;
        const NurbsSurface s = makeNurbsTorus(kCenter, R, r);
        double worst = 0.0;
        forGrid(s, 160, [&](double u, double v) {
            const glm::dvec3 p = evaluateNurbsPoint(s, u, v);
            const double d = axisDistance(p) - R, y = p.y - kCenter.y;
            worst = std::max(worst, std::abs(d * d + y * y - r * r) / (r * r));
        });
        QVERIFY2(worst <= 1e-9, qPrintable(QString("relative error of (ρ − R)² + y² − r²: %1").arg(worst)));
    }

    void cylinderAndTubePointsLieOnTheirSurfaces()
    {
        const NurbsSurface cylinder = makeNurbsCylinder(kCenter, 1.5, 3.0);
        forGrid(cylinder, 60, [&](double u, double v) {
            const glm::dvec3 p = evaluateNurbsPoint(cylinder, u, v);
            QVERIFY(std::abs(axisDistance(p) - 1.5) <= 1e-9 * 1.5);
            QVERIFY(std::abs(p.y - kCenter.y - (3.0 * v - 1.5)) <= 1e-12);
        });
        // Capped tube: v in [0,1] bottom disc, [1,2] side, [2,3] top disc.
        const NurbsSurface tube = makeNurbsCappedTube(kCenter, 1.5, 3.0);
        forGrid(tube, 90, [&](double u, double v) {
            const glm::dvec3 p = evaluateNurbsPoint(tube, u, v);
            const double y = p.y - kCenter.y, rho = axisDistance(p);
            if (v <= 1.0) {
                QVERIFY(std::abs(y + 1.5) <= 1e-12);
                QVERIFY(std::abs(rho - 1.5 * v) <= 1e-9);
            } else if (v <= 2.0) {
                QVERIFY(std::abs(rho - 1.5) <= 1e-9);
                QVERIFY(std::abs(y - (3.0 * (v - 1.0) - 1.5)) <= 1e-12);
            } else {
                QVERIFY(std::abs(y - 1.5) <= 1e-12);
                QVERIFY(std::abs(rho - 1.5 * (3.0 - v)) <= 1e-9);
            }
        });
    }

    void derivativesMatchCentralDifferences()
    {
        NurbsSurface patch = makeNurbsPatch(kCenter, 4.0, 3.0, 6, 5);
        // Make it curved and rational.
        for (std::size_t k = 0; k < patch.points.size(); ++k) {
            patch.points[k].y += 0.3 * std::sin(1.7 * double(k));
            patch.weights[k] = 0.5 + 0.25 * double(k % 5);
        }
        QVERIFY(!findNurbsProblem(patch));
        const NurbsSurface surfaces[] = {makeNurbsSphere(kCenter, 2.0), makeNurbsTorus(kCenter, 2.0, 0.5),
                                         makeNurbsCappedTube(kCenter, 1.0, 2.0), patch};
        for (const NurbsSurface& s : surfaces) {
            const ParameterRange ru = parameterRangeU(s), rv = parameterRangeV(s);
            const double hu = 1e-6 * ru.length(), hv = 1e-6 * rv.length();
            for (int a = 1; a < 40; ++a)
                for (int b = 1; b < 40; ++b) {
                    // Off the knots (the parameterisation is only C0 at the circle's double knots).
                    const double u = ru.begin + ru.length() * (a + 0.31) / 40.7;
                    const double v = rv.begin + rv.length() * (b + 0.43) / 40.9;
                    const NurbsSample sample = evaluateNurbs(s, u, v);
                    const glm::dvec3 du =
                        (evaluateNurbsPoint(s, u + hu, v) - evaluateNurbsPoint(s, u - hu, v)) / (2 * hu);
                    const glm::dvec3 dv =
                        (evaluateNurbsPoint(s, u, v + hv) - evaluateNurbsPoint(s, u, v - hv)) / (2 * hv);
                    const double scale = 1.0 + glm::length(sample.du) + glm::length(sample.dv);
                    QVERIFY2(glm::length(sample.du - du) <= 1e-6 * scale,
                             qPrintable(QString::fromStdString(s.name) + " ∂u at " + at(u, v)));
                    QVERIFY2(glm::length(sample.dv - dv) <= 1e-6 * scale,
                             qPrintable(QString::fromStdString(s.name) + " ∂v at " + at(u, v)));
                }
        }
    }

    void normalsAreUnitAndOutward()
    {
        const NurbsSurface sphere = makeNurbsSphere(kCenter, 2.0);
        forGrid(sphere, 80, [&](double u, double v) {
            const glm::dvec3 n = nurbsNormal(sphere, u, v);
            const glm::dvec3 radial = glm::normalize(evaluateNurbsPoint(sphere, u, v) - kCenter);
            QVERIFY2(std::abs(glm::length(n) - 1.0) <= 1e-12, qPrintable(at(u, v)));
            // Exact away from the poles; at the poles the nudged limit is within ~1e-6.
            QVERIFY2(glm::dot(n, radial) >= 1.0 - 1e-9, qPrintable(at(u, v)));
        });
        const NurbsSurface torus = makeNurbsTorus(kCenter, 2.0, 0.5);
        forGrid(torus, 80, [&](double u, double v) {
            const glm::dvec3 p = evaluateNurbsPoint(torus, u, v);
            const glm::dvec3 ring = kCenter + 2.0 * glm::normalize(glm::dvec3(p.x - kCenter.x, 0, p.z - kCenter.z));
            QVERIFY2(glm::dot(nurbsNormal(torus, u, v), glm::normalize(p - ring)) >= 1.0 - 1e-9, qPrintable(at(u, v)));
        });
        const NurbsSurface patch = makeNurbsPatch(kCenter, 2.0, 2.0, 5, 5);
        QVERIFY(glm::dot(nurbsNormal(patch, 0.3, 0.8), glm::dvec3(0, 1, 0)) >= 1.0 - 1e-12);
    }

    void poleNormalsAreFiniteAndOutward()
    {
        const NurbsSurface sphere = makeNurbsSphere(kCenter, 2.0);
        const NurbsSurface tube = makeNurbsCappedTube(kCenter, 1.0, 2.0);
        for (const double u : {0.0, 0.7, 2.0, 4.0}) {
            // The exact derivative ∂u vanishes at the pole...
            QVERIFY(glm::length(evaluateNurbs(sphere, u, 0.0).du) <= 1e-12);
            // ...but the normal is the limit: -y at the south pole, +y at the north pole.
            QVERIFY(glm::dot(nurbsNormal(sphere, u, 0.0), glm::dvec3(0, -1, 0)) >= 1.0 - 1e-9);
            QVERIFY(glm::dot(nurbsNormal(sphere, u, 2.0), glm::dvec3(0, 1, 0)) >= 1.0 - 1e-9);
            QVERIFY(glm::dot(nurbsNormal(tube, u, 0.0), glm::dvec3(0, -1, 0)) >= 1.0 - 1e-12);
            QVERIFY(glm::dot(nurbsNormal(tube, u, 3.0), glm::dvec3(0, 1, 0)) >= 1.0 - 1e-12);
        }
        // A net collapsed to one point has no normal anywhere: zero, not NaN.
        NurbsSurface point = makeNurbsPatch(kCenter, 1.0, 1.0, 4, 4);
        for (glm::dvec3& p : point.points)
            p = kCenter;
        const glm::dvec3 n = nurbsNormal(point, 0.5, 0.5);
        QVERIFY(n.x == 0.0 && n.y == 0.0 && n.z == 0.0);
    }

    void tiesKeepSeamsAndPoles()
    {
        NurbsSurface sphere = makeNurbsSphere(kCenter, 1.0);
        QVERIFY(isPole(sphere, NurbsSide::VBegin));
        QVERIFY(isPole(sphere, NurbsSide::VEnd));
        QVERIFY(!isPole(sphere, NurbsSide::UBegin)); // closed direction: no side
        // A seam point (0, 2) is tied to (8, 2).
        const std::vector<std::size_t> seam = linkedControlPoints(sphere, sphere.index(0, 2));
        QCOMPARE(seam, (std::vector<std::size_t>{sphere.index(0, 2), sphere.index(8, 2)}));
        // A pole point is tied to its whole row.
        QCOMPARE(linkedControlPoints(sphere, sphere.index(3, 0)).size(), std::size_t(9));
        QCOMPARE(linkedControlPoints(sphere, sphere.index(4, 2)), std::vector<std::size_t>{sphere.index(4, 2)});
        moveControlPoint(sphere, sphere.index(8, 2), kCenter + glm::dvec3(2, 0, 0));
        QVERIFY(!findNurbsProblem(sphere));
        QVERIFY(sphere.points[sphere.index(0, 2)] == kCenter + glm::dvec3(2, 0, 0));
        moveControlPoint(sphere, sphere.index(5, 4), kCenter + glm::dvec3(0, 3, 0));
        QVERIFY(isPole(sphere, NurbsSide::VEnd));
        setControlWeight(sphere, sphere.index(0, 1), 0.25);
        QCOMPARE(sphere.weights[sphere.index(8, 1)], 0.25);
        QVERIFY(!findNurbsProblem(sphere));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, moveControlPoint(sphere, 45, glm::dvec3(0.0)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, setControlWeight(sphere, 3, 0.0));
        // Moving a seam point alone opens the seam: refused with the twin's index.
        sphere.points[sphere.index(0, 3)] += glm::dvec3(0.1, 0, 0);
        const auto problem = findNurbsProblem(sphere);
        QVERIFY(problem.has_value());
        QCOMPARE(QString::fromStdString(problem->where), QString("points[35]"));
    }
};

QTEST_APPLESS_MAIN(TestNurbsSurface)
#include "tst_nurbs_surface.moc"
