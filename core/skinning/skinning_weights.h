#pragma once
/// \file
/// Proxy bones and initial skinning weights from a segmentation (thesis 4.1.1: "the bone
/// distribution and influence (weight computation) have been established driven by a
/// segmentation method"): one bone per segment, weights that blend smoothly across
/// segment borders.

#include "core/skinning/skinning_model.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

#include <glm/vec3.hpp>

#include <span>

namespace trimlab {

struct SkinningWeightOptions {
    /// Width of the blend across a segment border, in mesh edges (mean rest-pose edge
    /// lengths): the heat time is t = width² / 2, so a segment's indicator diffuses about
    /// `borderWidth` edges into its neighbours. 0: rigid weights (one bone per vertex).
    double borderWidth = 2.0;
};

/// One bone per label of `segmentation` (B = segmentation.count; bone b = segment b) with
/// weights from one implicit heat-diffusion step of the segment indicators χ_b on the rest
/// pose: (I + t·L) w_b = χ_b, L the graph Laplacian of `graph` with edge weights
/// ℓ̄ / ℓ_uv (inverse rest-pose edge length, scaled by the mean edge length ℓ̄; positive, so
/// I + tL is a symmetric M-matrix) — one sparse LDLᵀ factorisation for all bones.
/// Because (I + tL)·1 = 1 and Σ_b χ_b = 1, the w_b are non-negative and sum to 1 at every
/// vertex before truncation; each vertex then keeps its 4 largest (sparseInfluences).
/// Deep inside a segment the weight is ≈ 1 for its bone; near a border it blends.
/// `restPositions`: #V; `graph`: the rest mesh's vertex graph; `segmentation`: #V labels.
/// Throws std::invalid_argument when the sizes disagree or a label is ≥ count.
/// Cancellable (checked between bones); progress stage "weights", one item per bone.
[[nodiscard]] SkinningWeights segmentationWeights(const VertexGraph& graph, std::span<const glm::dvec3> restPositions,
                                                  const VertexLabeling& segmentation,
                                                  const SkinningWeightOptions& options = {},
                                                  const TaskControl& control = {});

/// Rigid weights: vertex j fully bound to bone segmentation.labels[j] (thesis 2.3.1).
[[nodiscard]] SkinningWeights rigidWeights(const VertexLabeling& segmentation);

/// Sparse convex weights from a dense #V×B matrix (row-major: dense[j·B + b]), keeping
/// each vertex's 4 largest positive weights rescaled to sum 1 (e.g. a rig's weights).
/// Throws std::invalid_argument when dense.size() ≠ #V·B or a value is not finite.
[[nodiscard]] SkinningWeights sparseWeightsFromDense(std::span<const double> dense, std::size_t vertexCount,
                                                     std::size_t boneCount);

} // namespace trimlab
