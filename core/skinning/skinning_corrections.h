#pragma once
/// \file
/// Skin corrections (thesis 4.1.2): rest-pose vertex displacements (eq. 4.12 / 4.16) and
/// non-negative, convex weight corrections (eq. 4.13–4.15 / 4.17), both computed per vertex
/// in closed form (a 3×3 solve, a small simplex-constrained least squares).

#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

#include <glm/vec3.hpp>

#include <vector>

namespace trimlab {

/// Rest-pose corrections e^V (eq. 4.12; for DQS eq. 4.16, whose per-vertex transforms are
/// rigid matrices): for every vertex the e_j minimising Σ_t ‖T_j^t (v_j^0 + e_j) − 𝐯_j^t‖²
/// over all #P poses, T_j^t from vertexRestToPose. T is affine, so T(v + e) = T v + N e
/// (N: the linear part; e has w = 0 as the thesis requires) and e_j solves the 3×3
/// normal equations (Σ_t NᵀN) e = Σ_t Nᵀ(𝐯 − T v). The rest pose's own term (N = I) keeps
/// the matrix invertible. Adding e to the rest positions cannot increase E_RMS for these
/// transforms (e = 0 is a candidate). `poses`: the original animation (#P × #V).
/// Progress stage "vertex corrections"; parallel over vertices, deterministic.
[[nodiscard]] std::vector<glm::dvec3> restPoseCorrections(const SkinningModel& model,
                                                          const std::vector<PosePositions>& poses, unsigned threads = 0,
                                                          const TaskControl& control = {});

struct WeightCorrectionOptions {
    /// Candidate bones of a vertex: its own influences plus, when set, those of its graph
    /// neighbours (so a border vertex can pick up the bone next door). At most `limit` survive.
    bool neighbourBones = true;
    unsigned threads = 0;
    std::size_t limit = kDefaultInfluences; ///< influences per vertex, 1 … kMaxInfluences
};

/// Weight corrections (eq. 4.13–4.15): per vertex, the convex weights w + e^W over its
/// candidate bones minimising Σ_t ‖Σ_b (w_b + e_b) Q_b^t 𝐯_j^{t−1} − 𝐯_j^t‖² — with the
/// original previous pose 𝐯^{t−1} as the thesis assumes (for DQS the rigid matrices of
/// Q̂_b^t are blended linearly, the linearisation of eq. 4.17). The constraints of eq. 4.15
/// (Σ (w + e) = 1, w + e ≥ 0) are imposed exactly: solveSimplexLeastSquares on the
/// Cholesky-like factor of the candidate Gram matrix (the difference columns Q_b 𝐯 − 𝐯, in
/// which the sum-to-one constraint makes the right-hand side vanish, so no cancellation).
/// More than options.limit non-zero weights: the largest are kept and solved again. A
/// vertex keeps its old weights unless the new ones are strictly better in this objective
/// (or the old ones exceed the limit). The result is convex to 1e-12 with ≤ options.limit
/// influences per vertex.
/// Progress stage "weight corrections"; parallel over vertices, deterministic.
[[nodiscard]] SkinningWeights correctedWeights(const SkinningModel& model, const std::vector<PosePositions>& poses,
                                               const VertexGraph& graph, const WeightCorrectionOptions& options = {},
                                               const TaskControl& control = {});

} // namespace trimlab
