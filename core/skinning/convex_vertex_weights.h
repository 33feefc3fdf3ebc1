#pragma once
/// \file
/// The best convex weights of one vertex over a few candidate bones, given the Gram matrix
/// G of its "difference columns" d_b (bone b's prediction of the vertex minus the target,
/// stacked over poses). Because the weights sum to 1, the residual Σ_b x_b·(prediction_b)
/// − target equals Σ_b x_b d_b, so the error is xᵀGx and the target drops out — no
/// cancellation between large positions. Used by the thesis's weight corrections (eq.
/// 4.13–4.15, skinning_corrections.h) and by the rigid decomposition's weight update
/// (rigid_skinning_decomposition.h); they differ only in how the columns are made.

#include "core/skinning/skinning_model.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace trimlab {

/// argmin xᵀ·gram·x over the simplex (x ≥ 0, Σx = 1) with at most `limit` (≤ kMaxInfluences)
/// non-zero entries: the exact simplex minimiser, and when it uses more than `limit` bones
/// the minimiser again over its `limit` largest. `bones`: the candidates (sorted,
/// distinct), one per row/column of `gram`. Returns `old` when it is within `limit` and the
/// new weights are not strictly better in xᵀGx (so repeated updates never raise the
/// error); `old`'s bones must be among `bones`.
[[nodiscard]] VertexInfluences bestConvexInfluences(const Eigen::MatrixXd& gram,
                                                    const std::vector<std::uint32_t>& bones,
                                                    const VertexInfluences& old,
                                                    std::size_t limit = kDefaultInfluences);

} // namespace trimlab
