#pragma once
/// \file
/// Geometry contraction by constrained Laplacian smoothing (Berenguer & Moreno III.A,
/// after Au et al. 2008): every iteration solves
///     [W_L·L; W_H]·V' = [0; W_H·V]      (eq. 2, least squares through eq. 5)
/// with the clamped cotangent Laplacian L of the current positions, then grows
/// W_L ← s_L·W_L and sets W_H,i ← W_H,i⁰·√(A_i⁰/A_i) (A_i: one-ring area), both capped.
/// After every solve, edges shorter than collapseFraction of the diagonal collapse
/// (contraction_remeshing.h): the system shrinks as the surface contracts. While the
/// connectivity stays, the normal matrix keeps its pattern, so the symbolic analysis
/// runs only when a collapse changed it and otherwise only the numeric factorization
/// repeats (symbolicAnalyses() / numericFactorizations()).
///
/// Stopping (the paper gives caps but no rule; Au et al. stop on the area ratio): the
/// surface area, not the volume, is watched. Once a part has contracted to a sheet its
/// enclosed volume is ≈ 0 (and its sign noise) while the area keeps falling as the
/// sheet contracts to a curve, so only the area tells the two apart. The contraction
/// stops when the area ratio falls below minAreaRatio, when it stops falling (with W_L
/// capped: the fixed point), when an iteration would RAISE it (that iteration diverged:
/// with W_L in the hundreds, near-degenerate triangles whose clamped cotangents are
/// negative admit solutions of L·V' ≈ 0 far from the surface; its result is discarded),
/// or after maxIterations. A rise comes late, when the limbs are curves already but wide
/// parts (a palm, a thick hub) are still sheets or blobs.

#include "core/util/task_control.h"
#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/contraction_options.h"

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace trimlab {

/// One contraction of one mesh. Not copyable; not thread-safe.
class ContractionSolver {
public:
    /// Prepares the Laplacian pattern, the normal-equation pattern and the weights of
    /// `mesh` (checked by checkSkeletonInput or equivalent: in-range indices, finite
    /// positions, no repeated index in a face). Solves nothing yet.
    /// Throws std::invalid_argument for an empty mesh or options out of range
    /// (non-positive W_H⁰, s_L < 1, non-positive caps, minAngleDegrees outside (0, 60),
    /// maxIterations < 1, negative medialWeight, medial points not one per vertex).
    /// `medial`: per mesh vertex its medial point or none (options.medialWeight; empty:
    /// no medial attraction).
    ContractionSolver(const TriangleMesh& mesh, const ContractionOptions& options,
                      std::span<const std::optional<glm::dvec3>> medial = {});
    ~ContractionSolver();
    ContractionSolver(const ContractionSolver&) = delete;
    ContractionSolver& operator=(const ContractionSolver&) = delete;

    /// One iteration (solve, then update weights and Laplacian). Returns false and does
    /// nothing once finished() is true. A solve that raises the area (see above) is
    /// discarded: positions stay, iterations() does not count it, finished() becomes
    /// true and warnings() says so. If the chosen factorization fails, it switches to
    /// Eigen's SimplicialLDLT (same ordering; noted in warnings()) and retries; throws
    /// std::runtime_error only if that fails too or the solution is not finite.
    bool iterate();

    /// Iterates until finished(), reporting TaskControl progress (stage "contraction",
    /// done = iterations, total = maxIterations) after every iteration and throwing
    /// OperationCancelled (positions then hold the last finished iteration) when stop is
    /// requested, checked before every iteration.
    void run(const TaskControl& control = {});

    /// True once one of the stopping rules above applied.
    [[nodiscard]] bool finished() const;

    /// #V current (contracted) positions of the INPUT vertices (vertices merged by the
    /// remeshing or the input decimation share one); before the first iterate, the input
    /// positions after the decimation.
    [[nodiscard]] const std::vector<glm::dvec3>& positions() const;
    /// #V: ‖(L·V')_i‖ of the last solve (L of that iteration, V' its result), in the
    /// mesh's units: how far vertex i still is from the average of its neighbours under
    /// the cotangent weights, the curvature the paper's Fig. 7 colours. Zeros before the
    /// first iteration.
    [[nodiscard]] const std::vector<double>& laplacianMagnitude() const;
    /// Vertices of the remeshed surface the next solve works on (#V before any collapse).
    [[nodiscard]] std::size_t vertexCount() const;
    /// Edge collapses of the remeshing so far.
    [[nodiscard]] std::size_t collapses() const;
    /// Accepted iterations (the positions are the result of this many solves).
    [[nodiscard]] int iterations() const;
    [[nodiscard]] int symbolicAnalyses() const;
    [[nodiscard]] int numericFactorizations() const;
    /// Current surface area / original surface area (1 before the first iteration).
    [[nodiscard]] double areaRatio() const;
    /// The W_L of the next iteration.
    [[nodiscard]] double contractionWeight() const;
    /// The factorization in use, e.g. "CHOLMOD supernodal LLᵀ, METIS ordering".
    [[nodiscard]] std::string solverDescription() const;
    /// Fallbacks and other notes for the user (e.g. "CHOLMOD failed: …; using Eigen
    /// SimplicialLDLT"). Empty when nothing unusual happened.
    [[nodiscard]] const std::vector<std::string>& warnings() const;

private:
    struct State;
    std::unique_ptr<State> m;
};

} // namespace trimlab
