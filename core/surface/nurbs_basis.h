#pragma once
/// \file
/// B-spline basis functions of one parameter direction of a NURBS surface (Cox–de Boor
/// recursion in the triangular form of Piegl & Tiller, "The NURBS Book", A2.1–A2.3):
/// knot-vector validation, knot span search, the p+1 non-zero basis values at a
/// parameter, and their first derivatives. Everything is double precision.
///
/// Conventions. A direction has `count` = n+1 control points and degree p, so its knot
/// vector has n+p+2 = count+p+1 knots U[0..m]. TrimLab uses **clamped** knot vectors
/// only: the first p+1 knots are equal and so are the last p+1, so the surface
/// interpolates its boundary control rows (this is what makes closed nets and poles
/// exact: a closed direction repeats its first control row as its last, as the exact
/// rational circle does). The parameter domain is [U[p], U[n+1]] = [U[0], U[m]].

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace trimlab {

/// Highest degree accepted anywhere (files, constructors). Degree 7 already needs 8×8
/// control points per evaluation; higher degrees are never needed for modelling here.
inline constexpr int kMaxNurbsDegree = 7;

/// What is wrong with a knot vector: `index` is the offending knot (or nullopt when the
/// vector as a whole is wrong, e.g. its size), `reason` is one sentence that says what to
/// do, e.g. "knots must not decrease (0.5 after 0.75); sort the knot vector".
struct KnotVectorProblem {
    std::optional<std::size_t> index;
    std::string reason;
};

/// Checks a knot vector for `count` control points of `degree`: 1 <= degree <=
/// kMaxNurbsDegree, count >= degree+1, size == count+degree+1, every knot finite, knots
/// non-decreasing, clamped ends (first degree+1 knots equal, last degree+1 knots equal, and
/// no more copies of the end knots),
/// no interior knot repeated more than `degree` times (the curve would break apart), and
/// a domain of positive length. Returns nullopt when the vector is valid.
[[nodiscard]] std::optional<KnotVectorProblem> findKnotVectorProblem(std::span<const double> knots, int degree,
                                                                     std::size_t count);

/// Throws std::invalid_argument "<what>: [knot K: ]REASON" when findKnotVectorProblem
/// reports a problem (`what` names the direction, e.g. "makeNurbsPatch knotsU").
void requireValidKnotVector(std::span<const double> knots, int degree, std::size_t count, const std::string& what);

/// The span index s with U[s] <= t < U[s+1] and degree <= s <= count−1; t at or beyond
/// the domain end gives the last non-empty span (count−1 for clamped vectors), t below
/// the domain start gives span `degree`. Binary search, O(log count). The knot vector
/// must be valid (checked by the caller once, not here: this runs per sample).
[[nodiscard]] std::size_t findKnotSpan(std::span<const double> knots, int degree, std::size_t count, double t);

/// The degree+1 basis values N_{span−degree..span, degree}(t) into `values` (size
/// degree+1). They are non-negative and sum to 1 (partition of unity) for t in the span.
void basisFunctions(std::span<const double> knots, int degree, std::size_t span, double t, std::span<double> values);

/// basisFunctions plus the first derivatives dN/dt of the same degree+1 functions into
/// `derivatives` (size degree+1; they sum to 0). Derivatives at a knot are those of the
/// span findKnotSpan picks (the right-hand side, except at the domain end).
void basisFunctionsAndDerivatives(std::span<const double> knots, int degree, std::size_t span, double t,
                                  std::span<double> values, std::span<double> derivatives);

/// All `count` basis values N_{i,degree}(t) (zero outside the local support), for tests
/// and tools that want the whole row. Same span rule as findKnotSpan.
[[nodiscard]] std::vector<double> allBasisFunctions(std::span<const double> knots, int degree, std::size_t count,
                                                    double t);

} // namespace trimlab
