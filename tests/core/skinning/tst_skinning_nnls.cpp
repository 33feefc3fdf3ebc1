// Non-negative and simplex-constrained least squares (core/skinning/nnls.h), the solver
// behind the convex weight corrections of thesis eq. 4.13–4.15: hand-checkable problems,
// the KKT conditions on random ones (including rank-deficient A), and bad input.
#include "core/skinning/nnls.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace trimlab;

namespace {

struct Problem {
    std::size_t rows = 0, cols = 0;
    std::vector<double> a; // column-major
    std::vector<double> b;
    [[nodiscard]] double at(std::size_t r, std::size_t c) const { return a[c * rows + r]; }
};

Problem randomProblem(std::mt19937& random, std::size_t rows, std::size_t cols, bool duplicateColumn)
{
    std::normal_distribution<double> n(0.0, 1.0);
    Problem p{rows, cols, std::vector<double>(rows * cols), std::vector<double>(rows)};
    for (double& v : p.a)
        v = n(random);
    for (double& v : p.b)
        v = n(random);
    if (duplicateColumn && cols > 1)
        std::copy_n(p.a.begin(), rows, p.a.begin() + std::ptrdiff_t(rows)); // column 1 = column 0
    return p;
}

// g = Aᵀ(Ax − b), the gradient of ½‖Ax − b‖².
std::vector<double> gradient(const Problem& p, const std::vector<double>& x)
{
    std::vector<double> residual(p.rows, 0.0), g(p.cols, 0.0);
    for (std::size_t r = 0; r < p.rows; ++r) {
        residual[r] = -p.b[r];
        for (std::size_t c = 0; c < p.cols; ++c)
            residual[r] += p.at(r, c) * x[c];
    }
    for (std::size_t c = 0; c < p.cols; ++c)
        for (std::size_t r = 0; r < p.rows; ++r)
            g[c] += p.at(r, c) * residual[r];
    return g;
}

} // namespace

class TestSkinningNnls : public QObject {
    Q_OBJECT
private slots:
    void handCheckedNnls();
    void handCheckedSimplex();
    void nnlsKktOnRandomProblems();
    void simplexKktOnRandomProblems();
    void badInputIsRejected();
};

void TestSkinningNnls::handCheckedNnls()
{
    // A = [1 0; 0 1; 1 1], b = (2, −1, 0). Unconstrained: x = (5/3, −4/3). With x₂ = 0:
    // min (x₁ − 2)² + 1 + x₁² gives x₁ = 1; residual (1, −1, −1), dual w = Aᵀr = (0, −2) ≤ 0.
    const std::vector<double> a = {1, 0, 1, 0, 1, 1};
    const std::vector<double> b = {2, -1, 0};
    const NnlsResult r = solveNnls(a, 3, 2, b);
    QVERIFY(r.converged);
    QVERIFY(std::abs(r.x[0] - 1.0) < 1e-14);
    QCOMPARE(r.x[1], 0.0);
    QVERIFY(std::abs(r.residualNorm - std::sqrt(3.0)) < 1e-14);

    // A = I, b = (1, −1): the negative component is clipped, x = (1, 0).
    const NnlsResult identity = solveNnls(std::vector<double>{1, 0, 0, 1}, 2, 2, std::vector<double>{1, -1});
    QCOMPARE(identity.x, (std::vector<double>{1.0, 0.0}));
}

void TestSkinningNnls::handCheckedSimplex()
{
    // A = I, b = (1, 1): the closest point of the segment x₁ + x₂ = 1 is (½, ½).
    const std::vector<double> identity = {1, 0, 0, 1};
    const NnlsResult half = solveSimplexLeastSquares(identity, 2, 2, std::vector<double>{1, 1});
    QVERIFY(std::abs(half.x[0] - 0.5) < 1e-14 && std::abs(half.x[1] - 0.5) < 1e-14);
    // b = (2, 0): on the line the optimum x₁ = 1.5 has x₂ = −0.5 < 0, so the vertex (1, 0).
    const NnlsResult corner = solveSimplexLeastSquares(identity, 2, 2, std::vector<double>{2, 0});
    QVERIFY(std::abs(corner.x[0] - 1.0) < 1e-14);
    QCOMPARE(corner.x[1], 0.0);
    // b a convex combination of the columns: recovered exactly.
    const std::vector<double> a = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const NnlsResult exact = solveSimplexLeastSquares(a, 3, 3, std::vector<double>{0.2, 0.3, 0.5});
    for (std::size_t i = 0; i < 3; ++i)
        QVERIFY(std::abs(exact.x[i] - std::vector<double>{0.2, 0.3, 0.5}[i]) < 1e-12);
    // C = A − b1ᵀ = 0: every point is optimal, the uniform one is returned.
    const NnlsResult flat = solveSimplexLeastSquares(std::vector<double>{1, 1}, 1, 2, std::vector<double>{1});
    QCOMPARE(flat.x, (std::vector<double>{0.5, 0.5}));
}

void TestSkinningNnls::nnlsKktOnRandomProblems()
{
    std::mt19937 random(7);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t rows = 3 + trial % 17, cols = 1 + trial % 9;
        const Problem p = randomProblem(random, rows, cols, trial % 5 == 0);
        const NnlsResult r = solveNnls(p.a, rows, cols, p.b);
        QVERIFY(r.converged);
        const std::vector<double> g = gradient(p, r.x);
        const double tolerance = 1e-10 * (1.0 + rows * cols);
        for (std::size_t c = 0; c < cols; ++c) {
            QVERIFY(r.x[c] >= 0.0);
            QVERIFY2(g[c] >= -tolerance, "dual feasibility: w = −g ≤ 0");
            if (r.x[c] > 0.0)
                QVERIFY2(std::abs(g[c]) <= tolerance, "complementary slackness");
        }
    }
}

void TestSkinningNnls::simplexKktOnRandomProblems()
{
    std::mt19937 random(11);
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t rows = 3 + trial % 13, cols = 1 + trial % 8;
        const Problem p = randomProblem(random, rows, cols, trial % 7 == 0);
        const NnlsResult r = solveSimplexLeastSquares(p.a, rows, cols, p.b);
        double sum = 0.0;
        for (double v : r.x) {
            QVERIFY(v >= 0.0);
            sum += v;
        }
        QVERIFY(std::abs(sum - 1.0) < 1e-12);
        // KKT with the multiplier μ of Σx = 1: g_j = −μ where x_j > 0, g_j ≥ −μ elsewhere.
        const std::vector<double> g = gradient(p, r.x);
        double mu = 0.0;
        double largest = 0.0;
        for (std::size_t c = 0; c < cols; ++c)
            if (r.x[c] > largest) {
                largest = r.x[c];
                mu = -g[c];
            }
        const double tolerance = 1e-8 * (1.0 + rows * cols);
        for (std::size_t c = 0; c < cols; ++c) {
            if (r.x[c] > 1e-9)
                QVERIFY2(std::abs(g[c] + mu) <= tolerance, "equal gradients on the support");
            QVERIFY2(g[c] + mu >= -tolerance, "no descent direction into a zero variable");
        }
    }
}

void TestSkinningNnls::badInputIsRejected()
{
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)solveNnls(std::vector<double>{1, 2, 3}, 2, 2, std::vector<double>{1, 2}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)solveNnls(std::vector<double>{1, NAN}, 2, 1, std::vector<double>{1, 2}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)solveSimplexLeastSquares({}, 0, 0, {}));
}

QTEST_APPLESS_MAIN(TestSkinningNnls)
#include "tst_skinning_nnls.moc"
