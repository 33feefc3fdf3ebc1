#pragma once
/// \file
/// Non-negative least squares (Lawson & Hanson, "Solving Least Squares Problems", 1974,
/// ch. 23, algorithm NNLS) and the simplex-constrained least squares the skinning weight
/// corrections need (thesis eq. 4.13–4.15: corrected weights non-negative and convex).
/// Dense and meant for small problems (a few to a few hundred unknowns).

#include <cstddef>
#include <span>
#include <vector>

namespace trimlab {

struct NnlsOptions {
    /// Outer iterations (one variable enters the passive set per iteration); 0: 3·cols.
    std::size_t maxIterations = 0;
    /// A variable may enter while its dual w_j = [Aᵀ(b − Ax)]_j exceeds this; 0: 10·ε·
    /// max(rows, cols)·(largest column norm of A)·‖b‖ (the scale of w's rounding error).
    double tolerance = 0.0;
};

struct NnlsResult {
    std::vector<double> x;     ///< cols values, every one ≥ 0
    double residualNorm = 0.0; ///< ‖A x − b‖₂
    std::size_t iterations = 0;
    bool converged = false; ///< false: stopped by maxIterations (x is still feasible)
};

/// min ‖A x − b‖₂ subject to x ≥ 0, by the Lawson–Hanson active-set method: variables
/// with the largest positive dual enter the passive set one at a time; the unconstrained
/// least-squares solution on the passive set (column-pivoting QR) is accepted when it is
/// positive, otherwise the step is cut back to the first variable that would turn
/// negative and that variable leaves. At the returned x the KKT conditions hold: x ≥ 0,
/// w = Aᵀ(b − Ax) ≤ tolerance, and w_j ≈ 0 where x_j > 0.
/// `a` is rows×cols, column-major (a[c·rows + r]); `b` has rows entries.
/// Throws std::invalid_argument when the sizes disagree or a value is not finite.
[[nodiscard]] NnlsResult solveNnls(std::span<const double> a, std::size_t rows, std::size_t cols,
                                   std::span<const double> b, const NnlsOptions& options = {});

/// min ‖A x − b‖₂ subject to x ≥ 0 and Σ x = 1 (x on the probability simplex), solved
/// exactly by one NNLS: with C = A − b·1ᵀ the objective is ‖C x‖ on the simplex, and
/// min_{y ≥ 0} ‖C y‖² + (1ᵀy − 1)² has, for y = s·x, the value s²q + (s − 1)² whose minimum
/// over s is q / (1 + q) with q = ‖C x‖² — increasing in q, so x = y / 1ᵀy minimises ‖C x‖
/// (the least-distance reduction of Lawson & Hanson, ch. 23.5). C is scaled by its
/// largest column norm first (the minimiser does not change) so q is O(1).
/// The returned x sums to 1 up to rounding (≈1e-16). When C = 0 every point is optimal and
/// the uniform x = 1/cols is returned. Same layout and errors as solveNnls; cols ≥ 1.
[[nodiscard]] NnlsResult solveSimplexLeastSquares(std::span<const double> a, std::size_t rows, std::size_t cols,
                                                  std::span<const double> b, const NnlsOptions& options = {});

} // namespace trimlab
