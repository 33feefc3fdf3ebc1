#pragma once
/// \file
/// The rigid (DQS) fit of one pose (thesis eq. 4.8 with the objective of eq. 4.6): the B
/// unit dual quaternions Q̂_b whose blended, normalised sandwich carries the source
/// positions onto the target pose.

#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace trimlab {

namespace detail {
struct BonePairPattern;
}

/// argmin over unit Q̂_1 … Q̂_B of Σ_j ‖DQS_j(Q̂) s_j − d_j‖², where DQS_j blends the
/// vertex's influences (blendDualQuaternions). The objective is not linear in Q̂, so:
/// 1. start from `initial` (B transforms) or, when it is empty, from each bone's
///    weighted Kabsch/Procrustes fit (vertex weights w_{b,j}², favouring the vertices the
///    bone dominates);
/// 2. refine all bones together by Levenberg–Marquardt on 6 parameters per bone (a
///    rotation vector about the bone's centroid and a translation): the per-vertex
///    Jacobian is the chain rule through the blend (the 3×8 blend-to-position derivative
///    in closed form, the 8×6 parameter-to-dual-quaternion one by central differences
///    once per bone), the 6B×6B normal equations share the bone-pair pattern of the
///    affine fit. Stops when a step lowers the error by less than a relative 1e-6.
/// An animation made by DQS from rigid bones is recovered to rounding. At most
/// options.rigidIterations LM steps. Requires source.size() == target.size() ==
/// weights.vertices.size() and initial.size() ∈ {0, B} (else std::invalid_argument).
[[nodiscard]] std::vector<DualQuaternion> fitRigidBoneTransforms(std::span<const glm::dvec3> source,
                                                                 std::span<const glm::dvec3> target,
                                                                 const SkinningWeights& weights,
                                                                 std::span<const DualQuaternion> initial = {},
                                                                 const PoseFitOptions& options = {});

/// The rigid motion x ↦ R x + t minimising Σ_i ω_i ‖R s_i + t − d_i‖² (weighted Kabsch;
/// a reflection is never returned). With fewer than 3 non-collinear weighted points the
/// rotation is not unique and one of the optimal ones is returned. All-zero weights give
/// the identity.
[[nodiscard]] DualQuaternion fitRigidMotion(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                                            std::span<const double> omega);

namespace detail {
[[nodiscard]] std::vector<DualQuaternion>
fitRigidBoneTransforms(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                       const SkinningWeights& weights, const BonePairPattern& pattern,
                       std::span<const DualQuaternion> initial, const PoseFitOptions& options);
}

} // namespace trimlab
