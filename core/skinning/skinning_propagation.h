#pragma once
/// \file
/// Pose editing with propagation (thesis 4.1.3, eq. 4.18–4.19): an edited pose p_e gets new
/// transforms Q̃^e (from the pose before it); every later pose keeps its own pose-to-pose
/// transforms and so follows the edit, T_j^t = T_j^{t,e+1}·(Σ_b w_{b,j} Q̃_b^e)·T_j^{e−1,1}
/// for t ≥ e, without any refitting; earlier poses do not change at all.
///
/// Reading of eq. 4.18–4.19: T_j^{t0,t1} is the product of the blended transforms
/// Σ_b w_{b,j} Q_b^t of the poses from t1 up to t0, the later pose on the left (as eq. 4.9
/// unrolled); an empty range (t1 past t0) is the identity. "Later" and "earlier" follow
/// the chain away from the rest pose (SkinningModel::previousPose), so with a rest pose
/// in the middle, editing a pose before it propagates towards pose 0.

#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace trimlab {

/// A copy of `model` with pose `pose` edited to `positions` (#V): its transforms are
/// refitted (SkinningPoseFitter, the model's method) to carry the model's reconstruction of
/// previousPose(pose) onto `positions`; all other transforms are copied, so
/// reconstructPoses of the result is bit-identical to the original's for every pose that
/// is not `pose` or after it. Editing the rest pose replaces the rest positions (rest-pose
/// editing, thesis Fig. 4.2) and every pose follows. For a RestToPose model only `pose`
/// changes. Throws std::invalid_argument for a pose out of range or a wrong vertex count.
[[nodiscard]] SkinningModel editPose(const SkinningModel& model, std::size_t pose,
                                     std::span<const glm::dvec3> positions, const PoseFitOptions& options = {});

/// A copy of `model` whose bone `bone` at pose `pose` has the transform `transform` (LBS
/// models) — the "changed bone transform" edit; later poses follow as for editPose.
/// Throws std::invalid_argument for a DQS model or indices out of range.
[[nodiscard]] SkinningModel setBoneTransform(const SkinningModel& model, std::size_t pose, std::size_t bone,
                                             const Affine3& transform);
/// The same for DQS models (a unit dual quaternion); throws for an LBS model.
[[nodiscard]] SkinningModel setBoneTransform(const SkinningModel& model, std::size_t pose, std::size_t bone,
                                             const DualQuaternion& transform);

/// Eq. 4.19 for vertex `vertex`: T^{later,earlier} = B^later · … · B^earlier where B^t is
/// blendedTransform(model, t, vertex) and the poses run along the chain from `earlier` to
/// `later`. Identity when `earlier` is not on the chain path from the rest pose to `later`
/// (an empty range such as T^{e−1,1} for e = 1).
[[nodiscard]] Affine3 chainProduct(const SkinningModel& model, std::size_t vertex, std::size_t later,
                                   std::size_t earlier);

/// Eq. 4.18: T_j^t after pose `edited` was given the blended transform `editedBlend`
/// (Σ_b w_{b,j} Q̃_b^e), from the transforms of `model` for every other pose:
/// chainProduct(t, next(e)) · editedBlend · chainProduct(previousPose(e), first pose after
/// the rest pose). `pose` must be `edited` or after it on the chain.
[[nodiscard]] Affine3 propagatedRestToPose(const SkinningModel& model, std::size_t vertex, std::size_t pose,
                                           std::size_t edited, const Affine3& editedBlend);

} // namespace trimlab
