#pragma once
/// \file
/// The affine (LBS) fit of one pose (thesis eq. 4.7 with the least-squares objective of
/// eq. 4.6): the B matrices Q_b that carry the source positions (pose t−1 for p2p, the
/// rest pose for classical skinning) onto the target pose.

#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace trimlab {

namespace detail {
struct BonePairPattern;
}

/// argmin over Q_1 … Q_B of Σ_j ‖Σ_b w_{b,j} Q_b s_j − d_j‖² (s = source, d = target; #V
/// each). The three output coordinates decouple, so this is one 4B×4B system with three
/// right-hand sides. Each bone is parameterised about the weighted centroid and scale of
/// its vertices, which keeps the system well conditioned whatever the model's position and
/// units. A relative damping of 1e-10 pulls under-determined bones (no vertices, or
/// coplanar ones) towards the identity — the right guess for the small pose-to-pose
/// motions of 4.1.1 — and changes a determined fit by ~1e-10 relative.
/// Requires source.size() == target.size() == weights.vertices.size() (else
/// std::invalid_argument).
[[nodiscard]] std::vector<Affine3> fitAffineBoneTransforms(std::span<const glm::dvec3> source,
                                                           std::span<const glm::dvec3> target,
                                                           const SkinningWeights& weights,
                                                           const PoseFitOptions& options = {});

namespace detail {
/// The same with the bone-pair pattern of `weights` computed once by the caller.
[[nodiscard]] std::vector<Affine3>
fitAffineBoneTransforms(std::span<const glm::dvec3> source, std::span<const glm::dvec3> target,
                        const SkinningWeights& weights, const BonePairPattern& pattern, const PoseFitOptions& options);

/// Weighted centroid and RMS radius of each bone's source vertices (weights w_{b,j}); a
/// bone without vertices gets the centroid of all vertices and radius 1.
struct BoneFrames {
    std::vector<glm::dvec3> centroid;
    std::vector<double> radius;
};
[[nodiscard]] BoneFrames boneFrames(std::span<const glm::dvec3> source, const SkinningWeights& weights);

/// Throws std::invalid_argument unless the three sizes agree.
void requireFitSizes(std::size_t source, std::size_t target, std::size_t weights);
} // namespace detail

} // namespace trimlab
