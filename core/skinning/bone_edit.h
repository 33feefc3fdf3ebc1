#pragma once
/// \file
/// Editing a pose by moving one bone (thesis 4.1.3, "changed bone transforms"): the user
/// gives a rotation about the bone's centroid and a translation; the bone's transform at
/// that pose becomes that rigid motion applied after its fitted transform, and the core
/// (skinning_propagation.h) carries the change to every later pose (eq. 4.18–4.19) with
/// no refit, earlier poses unchanged. This file only turns the user's numbers into the
/// transform the core takes.

#include "core/skinning/skinning_model.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace trimlab {

struct BoneEdit {
    /// Degrees about the x, y and z axes through the bone's centroid, applied in that
    /// order (R = R_z·R_y·R_x).
    glm::dvec3 rotationDegrees{0.0};
    /// Length units of the animation, applied after the rotation.
    glm::dvec3 translation{0.0};

    [[nodiscard]] bool isIdentity() const
    {
        return rotationDegrees == glm::dvec3(0.0) && translation == glm::dvec3(0.0);
    }
};

/// Σ_j w_{b,j}·p_j / Σ_j w_{b,j} over the vertices bone `bone` influences, on `positions`
/// (#V). Throws std::invalid_argument when the sizes differ or the bone has no weight.
[[nodiscard]] glm::dvec3 boneCentroid(const SkinningWeights& weights, std::span<const glm::dvec3> positions,
                                      std::size_t bone);

/// The rigid motion E: x ↦ R·(x − centre) + centre + translation of `edit`.
[[nodiscard]] Affine3 boneEditMotion(const BoneEdit& edit, const glm::dvec3& centre);

/// A copy of `model` in which bone `bone` at pose `pose` has the transform E∘Q (Q its
/// transform in `model`; for DQS the dual-quaternion product), E = boneEditMotion about
/// the bone's centroid on `posed` — the model's own positions of `pose`, where E acts.
/// Goes through setBoneTransform, so later poses follow and earlier ones are
/// bit-identical. Throws std::invalid_argument for indices out of range or the rest pose
/// (whose transform is the identity by definition and never applied).
[[nodiscard]] SkinningModel applyBoneEdit(const SkinningModel& model, std::size_t pose, std::size_t bone,
                                          const BoneEdit& edit, std::span<const glm::dvec3> posed);

} // namespace trimlab
