#pragma once
/// \file
/// Simplification of the contracted mesh into a curve skeleton (Berenguer & Moreno
/// III.B): first a natural pre-collapse of every edge shorter than δ (shortest first),
/// then Au et al.'s modified QEM collapse with the edge-based shape cost (eqs. 6–8) and
/// the sampling cost (eq. 9), until no triangle is left. Every collapse records which
/// original vertices each surviving node absorbed (the skeleton–mesh correspondence).

#include "core/util/task_control.h"
#include "core/skeleton/skeleton.h"

#include <glm/vec3.hpp>

#include <span>

namespace trimlab {

/// Simplification settings with the paper's defaults.
struct SimplificationOptions {
    /// δ of the pre-collapse, as a fraction of the bounding-box diagonal of the ORIGINAL
    /// mesh: 10⁻³, i.e. one pixel when the model fills a 1000-pixel view. Contracted
    /// cross-sections collapse far below that while consecutive cross-sections stay a
    /// mesh edge apart (≈ 1 % of the diagonal for 10k vertices, still ≈ 0.2 % at 250k),
    /// so the pre-collapse merges each section into one vertex and keeps the sampling
    /// along the curve for the QEM stage. ≤ 0 disables the pre-collapse.
    double preCollapseFraction = 1.0e-3;
    double shapeWeight = 1.0;    ///< w_a of eq. (10)
    double samplingWeight = 0.1; ///< w_b of eq. (10)

    friend bool operator==(const SimplificationOptions&, const SimplificationOptions&) = default;
};

/// The curve skeleton of the contracted mesh: `contracted` (#V contracted positions),
/// `triangles` (the mesh's connectivity, indices < #V, no repeated index in a face),
/// `delta` the absolute pre-collapse length (the caller scales preCollapseFraction).
/// Result: nodes at the contracted positions of the surviving vertices (in increasing
/// order of their vertex index), edges between them (first < second, no duplicates),
/// vertexNode (#V) for every vertex. Vertices no triangle uses join the node nearest to
/// their own contracted position. Only edges that still border a triangle collapse, so
/// skeleton edges (no triangle left) are never shortened and arm ends survive.
/// Reports stage "simplification" (done = collapses, total = #V − 1, every 1024
/// collapses) and throws OperationCancelled when stop is requested.
/// Collapse i → j costs w_a·F_a + w_b·F_b with F_a = v_jᵀ(Q_i + Q_j)v_j (the squared
/// distances from v_j to the lines of the edges that i and j absorbed; the printed
/// eq. (8) reads F_i(v_i) + F_j(v_j), but its text and Au et al. evaluate both at
/// v_j) and F_b = |v_i − v_j|·Σ_k |v_i − v_k| over the current edges of i.
[[nodiscard]] CurveSkeleton simplifyContractedMesh(std::span<const glm::dvec3> contracted,
                                                   std::span<const glm::uvec3> triangles, double delta,
                                                   const SimplificationOptions& options,
                                                   const TaskControl& control = {});

} // namespace trimlab
