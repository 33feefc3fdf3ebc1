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

/// Where the medial attraction's points come from (ContractionOptions::medialWeight).
/// - FilteredChordMidpoints: each vertex's inward chord midpoint, dropped where the chord
///   runs along a limb (medial_targets.h).
/// - ShrinkingBalls: the centre of each vertex's medial ball (shrinking_balls.h).
enum class MedialPoints { FilteredChordMidpoints, ShrinkingBalls };

/// Contraction settings with the paper's defaults (III.A, details 1–3).
struct ContractionOptions {
    /// W_L⁰, the initial contraction weight. ≤ 0 means 1. The paper gives 10⁻³·√Ā (Ā: mean
    /// face area); taken in the mesh's own units the formula depends on them, because the
    /// cotangent Laplacian and W_H are dimensionless, and even with Ā as the unit of area
    /// (10⁻³) the first solves move almost nothing: a tube of n vertices per ring starts to
    /// contract only once W_L ≈ (n/2π)². Starting at 1 gives the same contraction in about
    /// half the solves (docs/measurements/2026-11-29-skeleton-stages.md).
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
    /// Stop once the surface area has fallen below this fraction of the original (Au et
    /// al.'s criterion, who use 10⁻⁶). 10⁻³: by then the remaining area is in sections a
    /// fraction of a pixel wide, which the simplification's pre-collapse merges anyway;
    /// the solves on to 10⁻⁶ cost time without making the skeleton better.
    double minAreaRatio = 1.0e-3;
    /// Stop once an iteration with W_L at its cap reduces the surface area by less than
    /// this fraction: the contraction has reached its fixed point and further iterations
    /// cost time for nothing.
    double minAreaDecrease = 0.01;
    /// Remeshing while contracting (contraction_remeshing.h): after every solve, edges
    /// shorter than this fraction of the bounding-box diagonal collapse, so the system
    /// shrinks. ≤ 0 (the default) keeps every vertex, the paper's fixed connectivity.
    /// Off because it is slower (every changed pattern needs a new symbolic analysis) and
    /// worse: the collapses shorten the contracted limbs, the simplification then keeps
    /// fewer sections and more of the curve's length lies outside. Kept as an option for
    /// comparisons (with 0.002, where CGAL's mean-curvature-flow skeleton collapses).
    double collapseFraction = 0.0;
    /// A dense input — its median edge shorter than this fraction of the bounding-box
    /// diagonal — first has every edge shorter than that collapsed (the same collapses,
    /// once): it is contracted at the sampling its skeleton needs, and every input vertex
    /// follows the vertex it was merged into. 0.002 is CGAL's skeleton's edge length. A
    /// mesh at its natural sampling (median edge above it) is left as it is, slivers and
    /// all: the skeleton of a mesh is only as stable as its contraction, and a few
    /// collapses can turn a contracted arm into a hairpin (seen on the test star). A larger
    /// fraction would decimate meshes at their natural sampling as well and cost
    /// containment. ≤ 0 never decimates.
    double inputCollapseFraction = 0.002;
    SparseOrdering ordering = SparseOrdering::Metis;
    SparseBackend backend = SparseBackend::Cholmod;
    /// At most this many solves.
    int maxIterations = 20;
    /// μ, the medial attraction (an experiment; 0, the default, is Au et al.'s
    /// contraction): each vertex with a medial point M_i (medial_targets.h, given to the
    /// solver) is also pulled toward it with the weight μ·W_H,i, so a short limb contracts
    /// onto its axis instead of into the body along its length, as CGAL's mean-curvature
    /// flow does with its Voronoi poles. The least-squares row pair is folded into one:
    /// weight W_H,i·√(1 + μ²) toward (V_i + μ²·M_i)/(1 + μ²). Off: it brings lost legs and
    /// ears back, but which branches survive changes from one μ or medial-point source to
    /// the next (decided by the attraction itself, not by where its points come from), and
    /// the branch recovery (branch_recovery.h) brings lost limbs back after the contraction
    /// instead (the measurements: docs/measurements/2026-11-29-skeleton-stages.md).
    double medialWeight = 0.0;
    /// Where the medial points come from, with medialWeight > 0.
    MedialPoints medialPoints = MedialPoints::FilteredChordMidpoints;

    friend bool operator==(const ContractionOptions&, const ContractionOptions&) = default;
};

} // namespace trimlab
