#pragma once
/// \file
/// The sparse Cholesky factorizations behind ContractionSolver (paper IV, Table I): one
/// interface over CHOLMOD (through Eigen's CholmodSupport, the ordering chosen through
/// cholmod_common) and Eigen's SimplicialLDLT, each with AMD, COLAMD or METIS ordering.
/// The caller analyzes the pattern once and factorizes as often as the values change.
/// Internal to core/skeleton (exposes Eigen types; trimlab_core links Eigen privately).

#include "core/skeleton/contraction_options.h"
#include "core/skeleton/cotangent_laplacian.h"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace trimlab {

/// Factorization of a symmetric positive definite matrix given by its LOWER triangle
/// (entries above the diagonal are ignored). Methods return false and set `error` to a
/// sentence naming what failed; they never throw for numerical reasons.
class SparseCholesky {
public:
    virtual ~SparseCholesky() = default;
    /// Symbolic analysis: ordering, elimination tree, fill pattern. Depends on the
    /// pattern of `lower` only. Must run before factorize.
    virtual bool analyze(const SkeletonSparseMatrix& lower, std::string& error) = 0;
    /// Numeric factorization of `lower`, which must have the analyzed pattern.
    virtual bool factorize(const SkeletonSparseMatrix& lower, std::string& error) = 0;
    /// Solves for every column of `rhs` (#N×3) with the last factorization.
    virtual bool solve(const Eigen::MatrixX3d& rhs, Eigen::MatrixX3d& x, std::string& error) = 0;
    /// e.g. "CHOLMOD supernodal LLᵀ, METIS ordering"; after analyze it names the ordering
    /// that was actually used (CHOLMOD may substitute AMD when METIS would need too much
    /// memory, or when its library lacks METIS).
    [[nodiscard]] virtual std::string description() const = 0;
};

/// The factorization for `backend` and `ordering`. For SparseOrdering::Colamd,
/// `colamdSource` is the rectangular matrix A whose normal matrix AᵀA will be factorized
/// (its pattern only); COLAMD orders A's columns once and that permutation is applied
/// symmetrically before every factorization. Ignored for the other orderings.
[[nodiscard]] std::unique_ptr<SparseCholesky> makeSparseCholesky(SparseBackend backend, SparseOrdering ordering,
                                                                 const SkeletonSparseMatrix* colamdSource);

/// Whether this process's CHOLMOD library can order with METIS: analyzes a small matrix
/// with CHOLMOD_METIS as the only method and checks that METIS was used. Debian's
/// libcholmod3 is built with its Partition module and links libmetis5.
[[nodiscard]] bool cholmodHasMetis();

[[nodiscard]] const char* orderingName(SparseOrdering ordering);

} // namespace trimlab
