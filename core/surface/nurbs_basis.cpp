#include "core/surface/nurbs_basis.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace trimlab {

namespace {

std::string numberText(double value)
{
    std::ostringstream out;
    out.precision(17);
    out << value;
    return out.str();
}

std::optional<KnotVectorProblem> problem(std::optional<std::size_t> index, std::string reason)
{
    return KnotVectorProblem{index, std::move(reason)};
}

// Finite, non-decreasing, and no interior knot repeated more than `degree` times.
std::optional<KnotVectorProblem> findOrderProblem(std::span<const double> knots, int degree)
{
    std::size_t run = 1;
    for (std::size_t k = 0; k < knots.size(); ++k) {
        if (!std::isfinite(knots[k]))
            return problem(k, "knot is not a finite number; use finite values");
        if (k == 0)
            continue;
        if (knots[k] < knots[k - 1])
            return problem(k, "knots must not decrease (" + numberText(knots[k]) + " after " +
                                  numberText(knots[k - 1]) + "); sort the knot vector");
        run = knots[k] == knots[k - 1] ? run + 1 : 1;
        const bool interior = knots[k] != knots.front() && knots[k] != knots.back();
        if (interior && run > std::size_t(degree))
            return problem(k, "interior knot " + numberText(knots[k]) + " repeated " + std::to_string(run) +
                                  " times, more than the degree " + std::to_string(degree) +
                                  " (the surface would break apart); remove a copy");
    }
    return std::nullopt;
}

// First degree+1 and last degree+1 knots equal (clamped ends), and no more than those.
std::optional<KnotVectorProblem> findClampProblem(std::span<const double> knots, int degree)
{
    const std::size_t p = std::size_t(degree);
    const std::size_t last = knots.size() - 1;
    for (std::size_t k = 1; k <= p; ++k) {
        if (knots[k] != knots[0])
            return problem(k, "the first " + std::to_string(p + 1) +
                                  " knots must be equal (clamped knot vector); repeat the first knot degree+1 times");
        if (knots[last - k] != knots[last])
            return problem(last - k, "the last " + std::to_string(p + 1) +
                                         " knots must be equal (clamped knot vector); repeat the last knot degree+1 "
                                         "times");
    }
    if (!(knots[last] > knots[0]))
        return problem(std::nullopt, "the parameter domain is empty (all knots equal); use increasing knots");
    // More than degree+1 copies at an end: the outermost basis function vanishes
    // everywhere, and at that end of the domain no basis function is left (the point
    // would be 0/0).
    if (knots[p + 1] == knots[0])
        return problem(p + 1, "the first knot is repeated more than degree+1 = " + std::to_string(p + 1) +
                                  " times; repeat it exactly degree+1 times");
    if (knots[last - p - 1] == knots[last])
        return problem(last - p - 1, "the last knot is repeated more than degree+1 = " + std::to_string(p + 1) +
                                         " times; repeat it exactly degree+1 times");
    return std::nullopt;
}

} // namespace

std::optional<KnotVectorProblem> findKnotVectorProblem(std::span<const double> knots, int degree, std::size_t count)
{
    if (degree < 1 || degree > kMaxNurbsDegree)
        return problem(std::nullopt,
                       "degree " + std::to_string(degree) + " is outside 1.." + std::to_string(kMaxNurbsDegree));
    if (count < std::size_t(degree) + 1)
        return problem(std::nullopt, std::to_string(count) + " control points are too few for degree " +
                                         std::to_string(degree) +
                                         "; use at least degree+1 = " + std::to_string(degree + 1));
    if (knots.size() != count + std::size_t(degree) + 1)
        return problem(std::nullopt, std::to_string(knots.size()) + " knots, but " + std::to_string(count) +
                                         " control points of degree " + std::to_string(degree) +
                                         " need count+degree+1 = " + std::to_string(count + std::size_t(degree) + 1));
    if (auto order = findOrderProblem(knots, degree))
        return order;
    return findClampProblem(knots, degree);
}

void requireValidKnotVector(std::span<const double> knots, int degree, std::size_t count, const std::string& what)
{
    if (const auto found = findKnotVectorProblem(knots, degree, count))
        throw std::invalid_argument(what + ": " + (found->index ? "knot " + std::to_string(*found->index) + ": " : "") +
                                    found->reason);
}

std::size_t findKnotSpan(std::span<const double> knots, int degree, std::size_t count, double t)
{
    const std::size_t p = std::size_t(degree);
    const std::size_t n = count - 1;
    if (t >= knots[n + 1]) {
        // Domain end: the last non-empty span (clamped vectors: span n).
        std::size_t span = n;
        while (span > p && knots[span] == knots[span + 1])
            --span;
        return span;
    }
    if (t <= knots[p])
        return p;
    // Largest s in [p, n] with knots[s] <= t (then t < knots[s+1]).
    const auto begin = knots.begin() + std::ptrdiff_t(p);
    const auto end = knots.begin() + std::ptrdiff_t(n + 1);
    const auto it = std::upper_bound(begin, end, t);
    return std::size_t(it - knots.begin()) - 1;
}

void basisFunctions(std::span<const double> knots, int degree, std::size_t span, double t, std::span<double> values)
{
    std::span<double> none;
    basisFunctionsAndDerivatives(knots, degree, span, t, values, none);
}

void basisFunctionsAndDerivatives(std::span<const double> knots, int degree, std::size_t span, double t,
                                  std::span<double> values, std::span<double> derivatives)
{
    // Triangular table of degree-0..p basis values; the derivative of degree p uses the
    // degree p−1 values: N'_{i,p} = p (N_{i,p−1}/(u_{i+p}−u_i) − N_{i+1,p−1}/(u_{i+p+1}−u_{i+1})).
    constexpr int kMax = kMaxNurbsDegree + 1;
    const int p = degree;
    double left[kMax], right[kMax], current[kMax], previous[kMax];
    current[0] = 1.0;
    previous[0] = 1.0;
    for (int r = 1; r <= p; ++r) {
        left[r] = t - knots[span + 1 - std::size_t(r)];
        right[r] = knots[span + std::size_t(r)] - t;
        if (r == p)
            std::copy(current, current + p, previous); // degree p−1 values, kept for derivatives
        double saved = 0.0;
        for (int k = 0; k < r; ++k) {
            const double denominator = right[k + 1] + left[r - k];
            const double ratio = denominator != 0.0 ? current[k] / denominator : 0.0;
            current[k] = saved + right[k + 1] * ratio;
            saved = left[r - k] * ratio;
        }
        current[r] = saved;
    }
    std::copy(current, current + p + 1, values.begin());
    if (derivatives.empty())
        return;
    // previous[k] = N_{span−p+1+k, p−1}, k = 0..p−1.
    for (int k = 0; k <= p; ++k) {
        const std::size_t i = span - std::size_t(p) + std::size_t(k); // global index of N_{i,p}
        double d = 0.0;
        if (k >= 1) {
            const double span1 = knots[i + std::size_t(p)] - knots[i];
            if (span1 != 0.0)
                d += previous[k - 1] / span1;
        }
        if (k <= p - 1) {
            const double span2 = knots[i + std::size_t(p) + 1] - knots[i + 1];
            if (span2 != 0.0)
                d -= previous[k] / span2;
        }
        derivatives[std::size_t(k)] = double(p) * d;
    }
}

std::vector<double> allBasisFunctions(std::span<const double> knots, int degree, std::size_t count, double t)
{
    std::vector<double> all(count, 0.0);
    const std::size_t span = findKnotSpan(knots, degree, count, t);
    double local[kMaxNurbsDegree + 1];
    basisFunctions(knots, degree, span, t, std::span<double>(local, std::size_t(degree) + 1));
    for (int k = 0; k <= degree; ++k)
        all[span - std::size_t(degree) + std::size_t(k)] = local[k];
    return all;
}

} // namespace trimlab
