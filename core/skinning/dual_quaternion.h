#pragma once
/// \file
/// Unit dual quaternions for rigid motions and their blending (thesis 2.3.3, eq. 2.5 and
/// 4.3–4.5; Kavan et al. 2008). A dual quaternion q̂ = q_r + ε q_d represents the rigid
/// motion x ↦ R x + t with q_r the rotation and q_d = ½ (0, t) q_r.

#include "core/skinning/skinning_affine.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <span>

namespace trimlab {

struct DualQuaternion {
    glm::dquat real{1.0, 0.0, 0.0, 0.0}; ///< q_r (w, x, y, z); unit length for a rigid motion
    glm::dquat dual{0.0, 0.0, 0.0, 0.0}; ///< q_d; orthogonal to q_r for a rigid motion

    bool operator==(const DualQuaternion&) const = default;
};

/// The dual quaternion of x ↦ rotation·x + translation (`rotation` is normalised).
[[nodiscard]] DualQuaternion dualQuaternionFromRigid(const glm::dquat& rotation, const glm::dvec3& translation);

/// The product a·b: the motion "first b, then a" (as compose() for Affine3).
[[nodiscard]] DualQuaternion operator*(const DualQuaternion& a, const DualQuaternion& b);

/// Scales q̂ to unit real part and removes the component of the dual part along the real
/// part, so the result is an exact rigid motion. A zero real part (a degenerate blend,
/// e.g. two opposite rotations with equal weights) gives the identity.
[[nodiscard]] DualQuaternion normalized(const DualQuaternion& q);

/// The translation t of a unit dual quaternion: 2·q_d·q_r* (vector part).
[[nodiscard]] glm::dvec3 translationOf(const DualQuaternion& q);

/// The rigid matrix [R | t] of a unit dual quaternion.
[[nodiscard]] Affine3 toAffine(const DualQuaternion& q);

/// q̂ applied to point p: the sandwich q̂ p̂ q̂⁻¹ of eq. 2.5 for a unit q̂.
[[nodiscard]] glm::dvec3 transformPoint(const DualQuaternion& q, const glm::dvec3& p);

/// Dual quaternion linear blending (eq. 4.4 followed by the normalisation that makes the
/// sandwich of eq. 4.3 rigid): Σ w_i q̂_i with every q̂_i first given the sign whose real
/// part has a non-negative dot product with that of `pivot` (antipodality: q̂ and −q̂ are
/// the same motion, and blending them unaligned takes the long way round), then
/// normalised. `pivot` is normally the influence with the largest weight.
/// Requires transforms.size() == weights.size().
[[nodiscard]] DualQuaternion blendDualQuaternions(std::span<const DualQuaternion> transforms,
                                                  std::span<const double> weights, const DualQuaternion& pivot);

} // namespace trimlab
