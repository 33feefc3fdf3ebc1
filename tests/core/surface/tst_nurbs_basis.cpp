// B-spline basis functions (core/surface/nurbs_basis.h): partition of unity and
// non-negativity at many parameters (knots and domain ends included), derivatives
// against central differences, agreement with the textbook recursion written here
// independently, span search, and the refusal of bad knot vectors.
#include "core/surface/nurbs_basis.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace trimlab;

namespace {

struct KnotCase {
    const char* name;
    int degree;
    std::vector<double> knots;
};

std::vector<KnotCase> knotCases()
{
    return {
        {"linear uniform", 1, {0, 0, 1, 2, 3, 3}},
        {"quadratic circle", 2, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}},
        {"quadratic bezier", 2, {0, 0, 0, 1, 1, 1}},
        {"cubic uniform", 3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1}},
        {"cubic non-uniform", 3, {-1, -1, -1, -1, -0.9, 0.3, 0.3, 2.5, 7, 7, 7, 7}},
        {"quartic double knot", 4, {0, 0, 0, 0, 0, 0.4, 0.4, 1, 1, 1, 1, 1}},
        {"degree 7", 7, {0, 0, 0, 0, 0, 0, 0, 0, 0.5, 1, 1, 1, 1, 1, 1, 1, 1}},
    };
}

std::size_t countOf(const KnotCase& c)
{
    return c.knots.size() - std::size_t(c.degree) - 1;
}

// Parameters to test: 200 uniform steps, every knot, and points just beside each knot.
std::vector<double> testParameters(const KnotCase& c)
{
    const double a = c.knots.front(), b = c.knots.back();
    std::vector<double> t;
    for (int k = 0; k <= 200; ++k)
        t.push_back(a + (b - a) * k / 200.0);
    for (const double knot : c.knots) {
        t.push_back(knot);
        if (knot > a)
            t.push_back(knot - 1e-9 * (b - a));
        if (knot < b)
            t.push_back(knot + 1e-9 * (b - a));
    }
    return t;
}

// The Cox–de Boor recursion exactly as defined (0/0 := 0), half-open spans, with the last
// non-empty span closed at the domain end. Independent of the triangular algorithm.
double coxDeBoor(const std::vector<double>& U, int i, int p, double t)
{
    if (p == 0) {
        const double end = U.back();
        if (t == end) // belongs to the last non-empty span
            return U[std::size_t(i)] < end && U[std::size_t(i) + 1] == end ? 1.0 : 0.0;
        return U[std::size_t(i)] <= t && t < U[std::size_t(i) + 1] ? 1.0 : 0.0;
    }
    double value = 0.0;
    const double d1 = U[std::size_t(i + p)] - U[std::size_t(i)];
    const double d2 = U[std::size_t(i + p + 1)] - U[std::size_t(i + 1)];
    if (d1 > 0.0)
        value += (t - U[std::size_t(i)]) / d1 * coxDeBoor(U, i, p - 1, t);
    if (d2 > 0.0)
        value += (U[std::size_t(i + p + 1)] - t) / d2 * coxDeBoor(U, i + 1, p - 1, t);
    return value;
}

} // namespace

class TestNurbsBasis : public QObject {
    Q_OBJECT

private slots:
    void partitionOfUnityAndNonNegative()
    {
        for (const KnotCase& c : knotCases()) {
            QVERIFY2(!findKnotVectorProblem(c.knots, c.degree, countOf(c)), c.name);
            for (const double t : testParameters(c)) {
                const std::vector<double> all = allBasisFunctions(c.knots, c.degree, countOf(c), t);
                double sum = 0.0;
                for (const double n : all) {
                    QVERIFY2(n >= 0.0, qPrintable(QString("%1: N < 0 at t = %2").arg(c.name).arg(t, 0, 'g', 17)));
                    sum += n;
                }
                QVERIFY2(std::abs(sum - 1.0) <= 1e-14,
                         qPrintable(QString("%1: Σ N = %2 at t = %3").arg(c.name).arg(sum, 0, 'g', 17).arg(t)));
            }
        }
    }

    void matchesTheRecursiveDefinition()
    {
        for (const KnotCase& c : knotCases())
            for (const double t : testParameters(c)) {
                const std::vector<double> all = allBasisFunctions(c.knots, c.degree, countOf(c), t);
                for (std::size_t i = 0; i < all.size(); ++i) {
                    const double expected = coxDeBoor(c.knots, int(i), c.degree, t);
                    QVERIFY2(std::abs(all[i] - expected) <= 1e-13, qPrintable(QString("%1: N_%2(%3) = %4, recursion %5")
                                                                                  .arg(c.name)
                                                                                  .arg(i)
                                                                                  .arg(t, 0, 'g', 17)
                                                                                  .arg(all[i])
                                                                                  .arg(expected)));
                }
            }
    }

    void derivativesMatchCentralDifferences()
    {
        for (const KnotCase& c : knotCases()) {
            const double a = c.knots.front(), b = c.knots.back();
            const double h = 1e-6 * (b - a);
            for (int k = 1; k < 400; ++k) {
                const double t = a + (b - a) * (k + 0.37) / 400.5;
                // Central differences are valid only inside one span (basis derivatives jump
                // at knots of multiplicity ≥ degree).
                const std::size_t span = findKnotSpan(c.knots, c.degree, countOf(c), t);
                if (t - h < c.knots[span] || t + h >= c.knots[span + 1])
                    continue;
                std::vector<double> values(std::size_t(c.degree) + 1), derivatives(std::size_t(c.degree) + 1);
                basisFunctionsAndDerivatives(c.knots, c.degree, span, t, values, derivatives);
                const std::vector<double> plus = allBasisFunctions(c.knots, c.degree, countOf(c), t + h);
                const std::vector<double> minus = allBasisFunctions(c.knots, c.degree, countOf(c), t - h);
                double derivativeSum = 0.0;
                for (int j = 0; j <= c.degree; ++j) {
                    const std::size_t i = span - std::size_t(c.degree) + std::size_t(j);
                    const double numeric = (plus[i] - minus[i]) / (2.0 * h);
                    // Truncation error h²/6·N''' plus rounding 1e-16/h, relative to the scale
                    // of the derivatives (degree / shortest span).
                    const double scale = c.degree / (c.knots[span + 1] - c.knots[span]);
                    QVERIFY2(std::abs(derivatives[std::size_t(j)] - numeric) <= 1e-6 * scale,
                             qPrintable(QString("%1: N'_%2(%3) = %4, difference quotient %5")
                                            .arg(c.name)
                                            .arg(i)
                                            .arg(t)
                                            .arg(derivatives[std::size_t(j)])
                                            .arg(numeric)));
                    derivativeSum += derivatives[std::size_t(j)];
                }
                QVERIFY(std::abs(derivativeSum) <= 1e-10 * c.degree / (c.knots[span + 1] - c.knots[span]));
            }
        }
    }

    void spanSearch()
    {
        const std::vector<double> U{0, 0, 0, 1, 2, 2, 3, 3, 3}; // degree 2, 6 control points
        QCOMPARE(findKnotSpan(U, 2, 6, 0.0), std::size_t(2));
        QCOMPARE(findKnotSpan(U, 2, 6, 0.5), std::size_t(2));
        QCOMPARE(findKnotSpan(U, 2, 6, 1.0), std::size_t(3));
        QCOMPARE(findKnotSpan(U, 2, 6, 2.0), std::size_t(5));
        QCOMPARE(findKnotSpan(U, 2, 6, 2.99), std::size_t(5));
        QCOMPARE(findKnotSpan(U, 2, 6, 3.0), std::size_t(5)); // domain end: last span
        QCOMPARE(findKnotSpan(U, 2, 6, 7.0), std::size_t(5));
        QCOMPARE(findKnotSpan(U, 2, 6, -1.0), std::size_t(2));
    }

    void endsInterpolate()
    {
        // Clamped ends: N_0 = 1 at the start and N_{n} = 1 at the end.
        for (const KnotCase& c : knotCases()) {
            const std::vector<double> first = allBasisFunctions(c.knots, c.degree, countOf(c), c.knots.front());
            const std::vector<double> last = allBasisFunctions(c.knots, c.degree, countOf(c), c.knots.back());
            QCOMPARE(first.front(), 1.0);
            QCOMPARE(last.back(), 1.0);
        }
    }

    void badKnotVectorsRefused_data()
    {
        QTest::addColumn<int>("degree");
        QTest::addColumn<int>("count");
        QTest::addColumn<std::vector<double>>("knots");
        QTest::addColumn<QString>("message");
        QTest::newRow("decreasing") << 2 << 4 << std::vector<double>{0, 0, 0, 0.75, 0.5, 1, 1}
                                    << "test: knot 4: knots must not decrease (0.5 after 0.75); sort the knot vector";
        QTest::newRow("too short") << 2 << 4 << std::vector<double>{0, 0, 0, 1, 1, 1}
                                   << "test: 6 knots, but 4 control points of degree 2 need count+degree+1 = 7";
        QTest::newRow("nan") << 1 << 2 << std::vector<double>{0, 0, std::nan(""), 1}
                             << "test: knot 2: knot is not a finite number; use finite values";
        QTest::newRow("not clamped") << 2 << 4 << std::vector<double>{0, 0, 0.1, 0.5, 1, 1, 1}
                                     << "test: knot 2: the first 3 knots must be equal (clamped knot vector); repeat "
                                        "the first knot degree+1 times";
        QTest::newRow("empty domain") << 1 << 2 << std::vector<double>{1, 1, 1, 1}
                                      << "test: the parameter domain is empty (all knots equal); use increasing knots";
        QTest::newRow("degree 0") << 0 << 2 << std::vector<double>{0, 1, 2} << "test: degree 0 is outside 1..7";
        QTest::newRow("degree 8") << 8 << 9 << std::vector<double>(18, 0.0) << "test: degree 8 is outside 1..7";
        QTest::newRow("too few points") << 3 << 3 << std::vector<double>{0, 0, 0, 1, 1, 1, 1}
                                        << "test: 3 control points are too few for degree 3; use at least degree+1 = 4";
        QTest::newRow("interior multiplicity")
            << 2 << 6 << std::vector<double>{0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}
            << "test: knot 5: interior knot 0.5 repeated 3 times, more than the degree 2 (the surface would break "
               "apart); remove a copy";
    }

    void badKnotVectorsRefused()
    {
        QFETCH(int, degree);
        QFETCH(int, count);
        QFETCH(std::vector<double>, knots);
        QFETCH(QString, message);
        QVERIFY(findKnotVectorProblem(knots, degree, std::size_t(count)).has_value());
        try {
            requireValidKnotVector(knots, degree, std::size_t(count), "test");
            QFAIL("accepted a bad knot vector");
        } catch (const std::invalid_argument& error) {
            QCOMPARE(QString::fromStdString(error.what()), message);
        }
    }
};

QTEST_APPLESS_MAIN(TestNurbsBasis)
#include "tst_nurbs_basis.moc"
