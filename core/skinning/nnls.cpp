#include "core/skinning/nnls.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;

void requireProblem(std::span<const double> a, std::size_t rows, std::size_t cols, std::span<const double> b)
{
    if (a.size() != rows * cols || b.size() != rows)
        throw std::invalid_argument("NNLS: A has " + std::to_string(a.size()) + " values and b " +
                                    std::to_string(b.size()) + " for a " + std::to_string(rows) + "×" +
                                    std::to_string(cols) + " problem");
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!std::all_of(a.begin(), a.end(), finite) || !std::all_of(b.begin(), b.end(), finite))
        throw std::invalid_argument("NNLS: A or b holds a value that is not finite");
}

// The least-squares solution of A_P z = b on the passive columns (z is 0 elsewhere).
Vector passiveSolution(const Matrix& a, const Vector& b, const std::vector<bool>& passive)
{
    std::vector<Eigen::Index> columns;
    for (std::size_t j = 0; j < passive.size(); ++j)
        if (passive[j])
            columns.push_back(Eigen::Index(j));
    Matrix ap(a.rows(), Eigen::Index(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k)
        ap.col(Eigen::Index(k)) = a.col(columns[k]);
    const Vector zp = ap.colPivHouseholderQr().solve(b);
    Vector z = Vector::Zero(a.cols());
    for (std::size_t k = 0; k < columns.size(); ++k)
        z(columns[k]) = zp(Eigen::Index(k));
    return z;
}

// The inner loop of Lawson–Hanson: moves x towards the passive solution until every
// passive variable is positive, dropping the ones that reach zero. Returns false when the
// entering variable `entering` does not come out positive (a rounding-level dual).
bool updatePassiveSet(const Matrix& a, const Vector& b, std::vector<bool>& passive, Vector& x, Eigen::Index entering)
{
    for (Eigen::Index guard = 0; guard <= a.cols(); ++guard) {
        const Vector z = passiveSolution(a, b, passive);
        if (guard == 0 && z(entering) <= 0.0)
            return false;
        double alpha = 1.0;
        bool allPositive = true;
        for (Eigen::Index j = 0; j < a.cols(); ++j)
            if (passive[std::size_t(j)] && z(j) <= 0.0) {
                allPositive = false;
                alpha = std::min(alpha, x(j) / (x(j) - z(j)));
            }
        if (allPositive) {
            x = z;
            return true;
        }
        x += alpha * (z - x);
        for (Eigen::Index j = 0; j < a.cols(); ++j)
            if (passive[std::size_t(j)] && x(j) <= 0.0) {
                passive[std::size_t(j)] = false;
                x(j) = 0.0;
            }
    }
    return true;
}

double defaultTolerance(const Matrix& a, const Vector& b)
{
    const double columnNorm = a.cols() > 0 ? a.colwise().norm().maxCoeff() : 0.0;
    return 10.0 * std::numeric_limits<double>::epsilon() * double(std::max(a.rows(), a.cols())) * columnNorm * b.norm();
}

} // namespace

NnlsResult solveNnls(std::span<const double> aValues, std::size_t rows, std::size_t cols,
                     std::span<const double> bValues, const NnlsOptions& options)
{
    requireProblem(aValues, rows, cols, bValues);
    const Matrix a = Eigen::Map<const Matrix>(aValues.data(), Eigen::Index(rows), Eigen::Index(cols));
    const Vector b = Eigen::Map<const Vector>(bValues.data(), Eigen::Index(rows));
    const double tolerance = options.tolerance > 0.0 ? options.tolerance : defaultTolerance(a, b);
    const std::size_t maxIterations = options.maxIterations > 0 ? options.maxIterations : 3 * cols;

    NnlsResult result;
    Vector x = Vector::Zero(Eigen::Index(cols));
    std::vector<bool> passive(cols, false);
    std::vector<bool> refused(cols, false); // duals that proved to be rounding noise
    while (true) {
        const Vector w = a.transpose() * (b - a * x);
        Eigen::Index entering = -1;
        for (Eigen::Index j = 0; j < Eigen::Index(cols); ++j)
            if (!passive[std::size_t(j)] && !refused[std::size_t(j)] && w(j) > tolerance &&
                (entering < 0 || w(j) > w(entering)))
                entering = j;
        if (entering < 0) {
            result.converged = true;
            break;
        }
        if (result.iterations == maxIterations)
            break;
        ++result.iterations;
        passive[std::size_t(entering)] = true;
        if (!updatePassiveSet(a, b, passive, x, entering)) {
            passive[std::size_t(entering)] = false;
            refused[std::size_t(entering)] = true;
            continue;
        }
        std::fill(refused.begin(), refused.end(), false);
    }
    result.x.assign(x.data(), x.data() + x.size());
    result.residualNorm = (a * x - b).norm();
    return result;
}

NnlsResult solveSimplexLeastSquares(std::span<const double> aValues, std::size_t rows, std::size_t cols,
                                    std::span<const double> bValues, const NnlsOptions& options)
{
    requireProblem(aValues, rows, cols, bValues);
    if (cols == 0)
        throw std::invalid_argument("simplex least squares: no unknowns");
    const Matrix a = Eigen::Map<const Matrix>(aValues.data(), Eigen::Index(rows), Eigen::Index(cols));
    const Vector b = Eigen::Map<const Vector>(bValues.data(), Eigen::Index(rows));
    Matrix c = a.colwise() - b; // C = A − b·1ᵀ
    const double scale = c.colwise().norm().maxCoeff();
    NnlsResult result;
    if (!(scale > 0.0)) {
        result.x.assign(cols, 1.0 / double(cols));
        result.converged = true;
        return result;
    }
    Matrix augmented(Eigen::Index(rows) + 1, Eigen::Index(cols));
    augmented.topRows(Eigen::Index(rows)) = c / scale;
    augmented.row(Eigen::Index(rows)).setOnes();
    Vector rhs = Vector::Zero(Eigen::Index(rows) + 1);
    rhs(Eigen::Index(rows)) = 1.0;
    NnlsResult y = solveNnls({augmented.data(), std::size_t(augmented.size())}, rows + 1, cols,
                             {rhs.data(), std::size_t(rhs.size())}, options);
    double sum = 0.0;
    for (double v : y.x)
        sum += v;
    Vector x(static_cast<Eigen::Index>(cols));
    for (std::size_t j = 0; j < cols; ++j)
        x(Eigen::Index(j)) = sum > 0.0 ? y.x[j] / sum : 1.0 / double(cols);
    result.x.assign(x.data(), x.data() + x.size());
    result.residualNorm = (a * x - b).norm();
    result.iterations = y.iterations;
    result.converged = y.converged;
    return result;
}

} // namespace trimlab
