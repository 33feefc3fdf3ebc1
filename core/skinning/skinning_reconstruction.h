#pragma once
/// \file
/// Evaluating a SkinningModel: the skinned positions of every pose by the pose-to-pose
/// formulas (thesis eq. 4.7, 4.8), and the equivalent per-vertex rest-to-pose transforms
/// T_j^t (eq. 4.9; for DQS eq. 4.10–4.11) that a classical skinning renderer would use.

#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace trimlab {

/// #V positions of one pose, in double precision.
using PosePositions = std::vector<glm::dvec3>;

/// The bracket of eq. 4.7 / 4.8 for vertex `vertex` at pose `pose`: Σ_b w_{b,j} Q_b^t (LBS),
/// or the rigid matrix of the blended, normalised dual quaternion Σ_b w_{b,j} Q̂_b^t (DQS;
/// blendDualQuaternions with the largest-weight influence as pivot). Indices must be in
/// range (checked by assert only).
[[nodiscard]] Affine3 blendedTransform(const SkinningModel& model, std::size_t pose, std::size_t vertex);

/// Every pose of the model: #P × #V positions, the rest pose being `restPositions` and
/// pose t being blendedTransform(t) applied to pose previousPose(t) (eq. 4.7 / 4.8).
[[nodiscard]] std::vector<PosePositions> reconstructPoses(const SkinningModel& model);

/// One pose, walking the chain from the rest pose (O(#V × chain length)).
[[nodiscard]] PosePositions reconstructPose(const SkinningModel& model, std::size_t pose);

/// T_j^t of vertex `vertex` for every pose t (eq. 4.9: T_j^t = [Σ_b w_{b,j} Q_b^t]·T_j^{t−1},
/// T_j^rest = identity; the DQS product of rigid matrices is the dual-quaternion product
/// Ô_j^t of eq. 4.10, whose inverse pair is eq. 4.11). `out` is resized to #P.
/// T_j^t·v_j^0 equals reconstructPoses(model)[t][j] up to rounding.
void vertexRestToPose(const SkinningModel& model, std::size_t vertex, std::vector<Affine3>& out);

/// T_j^t of every vertex for one pose: #V transforms.
[[nodiscard]] std::vector<Affine3> restToPoseTransforms(const SkinningModel& model, std::size_t pose);

/// Converts a pose of float positions to double.
[[nodiscard]] PosePositions toDoublePositions(const std::vector<glm::vec3>& positions);

} // namespace trimlab
