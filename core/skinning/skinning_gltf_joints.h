#pragma once
/// \file
/// Rigid joint motions for exporting a SkinningModel as a glTF skin (skinning_gltf.h).
/// glTF skinning is linear blend skinning of joint matrices built from translation,
/// rotation and scale, so every bone needs, per pose, a rigid rest-to-pose motion
/// x ↦ R x + t. This file derives them from any model:
/// - the bone's own rest-to-pose transform: the rest-to-pose model's transform, or for a
///   pose-to-pose model the product of the bone's transforms along the chain
///   (Q_b^t · Q_b^{t−1} ⋯, the pose before on the right, as eq. 4.9 for one bone);
/// - its rigid part: for DQS the motion of that dual quaternion; for LBS the closest
///   rotation to the affine matrix's linear part (polar decomposition), which drops scale
///   and shear but keeps the rotation they were mixed with, and the translation that keeps
///   the bone exact at its pivot;
/// - from that start, and also from the motions found for the chain's previous pose
///   (temporal coherence; it rescues bones whose chained affine product has drifted or
///   overflowed), the rigid motions of all bones of a pose are fitted together to the
///   target positions as LBS of rigid joints (RigidJointSolver: least-squares
///   translations, per-bone weighted Procrustes), which can only lower the error; the
///   better of the two results is kept. For an
///   affine fit this recovers part of what the dropped shear and scale moved; for a DQS
///   fit it absorbs part of the difference between DQS blending and glTF's linear blend;
///   for rigid motions that reproduce the target exactly nothing changes.

#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_reconstruction.h"
#include "core/skinning/skinning_rigid_joint_solver.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

/// #P × B rigid joint motions and the B joint pivots (the weighted centroid Σ_j w_bj v_j /
/// Σ_j w_bj of each bone's rest positions; the origin for a bone no vertex uses).
struct RigidJointAnimation {
    std::vector<glm::dvec3> pivots;
    std::vector<std::vector<RigidJointPose>> poses;
};

/// The bone transforms from the rest pose (#P × B): identity at the rest pose; for DQS
/// models the rigid matrices of the composed dual quaternions.
[[nodiscard]] std::vector<std::vector<Affine3>> boneRestToPose(const SkinningModel& model);

/// The rigid joint motions described in the file comment, fitted to `target` (#P × #V:
/// the original animation, or reconstructPoses(model)). Throws std::invalid_argument when
/// `target` does not have the model's pose and vertex counts.
[[nodiscard]] RigidJointAnimation rigidJointAnimation(const SkinningModel& model,
                                                      const std::vector<PosePositions>& target);

/// Linear blend skinning with rigid joints: per pose, v_j ↦ Σ_i w_i (R_i v_j + t_i) over
/// the vertex's influences, with `weights` (#V; they are divided by their sum, as a glTF
/// loader does). `restPositions`: #V.
[[nodiscard]] std::vector<PosePositions> rigidSkinPositions(const std::vector<glm::dvec3>& restPositions,
                                                            const SkinningWeights& weights,
                                                            const RigidJointAnimation& joints);

} // namespace trimlab
