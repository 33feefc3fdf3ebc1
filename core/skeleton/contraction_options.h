#pragma once
/// \file
/// The settings of geometry contraction (Berenguer & Moreno III.A, after Au et al. 2008):
/// the weights of the constrained Laplacian smoothing, their caps, the stopping rule and
/// how the normal equations are solved (paper IV, Table I: METIS + Cholesky is fastest).

namespace trimlab {

/// The fill-reducing ordering of the normal-equation matrix AᵀA (paper IV, Table I).
/// - Amd: approximate minimum degree on AᵀA.
/// - Colamd: column approximate minimum degree on A itself (the ordering for AᵀA that
///   COLAMD is made for). CHOLMOD's own CHOLMOD_COLAMD setting applies AMD to a
///   symmetric matrix, so this ordering is computed once from A's pattern and applied
///   as a symmetric permutation before the factorization (which then keeps it as given).
/// - Metis: METIS nested dissection (METIS_NodeND) on AᵀA.
enum class SparseOrdering { Amd, Colamd, Metis };

/// Which sparse Cholesky factorization solves the normal equations.
/// - Cholmod: SuiteSparse CHOLMOD through Eigen's CholmodSupport (supernodal or
///   simplicial as CHOLMOD decides), the ordering set through cholmod_common.
/// - EigenSimplicialLdlt: Eigen's SimplicialLDLT (with Eigen's AMD ordering, Eigen's
///   METIS ordering, or the COLAMD permutation). Also the fallback when CHOLMOD fails.
enum class SparseBackend { Cholmod, EigenSimplicialLdlt };

/// Contraction settings with the paper's defaults (III.A, details 1–3).
struct ContractionOptions {
    /// W_L⁰, the initial contraction weight. ≤ 0 means 10⁻³: the paper's
    /// 10⁻³·√Ā (Ā: mean face area) with Ā as the unit of area. Taken in the mesh's own
    /// units the formula depends on them, because the cotangent Laplacian and W_H are
    /// dimensionless: the unit-size 7,949-vertex cat would start at W_L⁰ ≈ 3·10⁻⁵ and,
    /// after 20 iterations (W_L ≈ 15), keep 62 % of its area, where W_L⁰ = 10⁻³ brings it
    /// to 11 %. A tube of n vertices per ring starts to contract once W_L ≈ (n/2π)²,
    /// whatever its size.
    double initialContractionWeight = 0.0;
    /// W_H⁰, the initial attraction weight of every vertex.
    double initialAttractionWeight = 1.0;
    /// s_L: W_L is multiplied by this after every iteration.
    double contractionGrowth = 2.0;
    /// Caps against over-contraction (III.A, detail 3): W_L ≤ 2048, W_H ≤ 10000.
    double maxContractionWeight = 2048.0;
    double maxAttractionWeight = 10000.0;
    /// Interior angles are clamped to [minAngle, 180° − minAngle] before taking
    /// cotangents (III.A, detail 1), so |cot| ≤ cot(minAngle) as triangles collapse.
    double minAngleDegrees = 1.0;
    /// Stop once the surface area has fallen below this fraction of the original
    /// (Au et al.'s criterion; the mesh is then a curve for every practical purpose).
    double minAreaRatio = 1.0e-6;
    /// Stop once an iteration with W_L at its cap reduces the surface area by less than
    /// this fraction: the contraction has reached its fixed point and further iterations
    /// cost time for nothing.
    double minAreaDecrease = 0.01;
    SparseOrdering ordering = SparseOrdering::Metis;
    SparseBackend backend = SparseBackend::Cholmod;
    /// At most this many solves.
    int maxIterations = 20;
};

} // namespace trimlab
