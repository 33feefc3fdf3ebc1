#pragma once
/// \file
/// An affine map of 3D space in double precision: the bone transforms M_b^t / Q_b^t of
/// linear blend skinning (thesis 2.3.2, eq. 2.3–2.4, 4.7) and the per-vertex rest-to-pose
/// transforms T_j^t (eq. 4.9), whose homogeneous 4×4 form has the last row (0 0 0 1).

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace trimlab {

/// x ↦ linear·x + translation. The default is the identity.
struct Affine3 {
    glm::dmat3 linear{1.0};      ///< the upper-left 3×3 block N (column-major, as glm)
    glm::dvec3 translation{0.0}; ///< T, in the animation's length units

    [[nodiscard]] glm::dvec3 apply(const glm::dvec3& p) const { return linear * p + translation; }
    bool operator==(const Affine3&) const = default;
};

/// a∘b: x ↦ a(b(x)) — the homogeneous product A·B.
[[nodiscard]] inline Affine3 compose(const Affine3& a, const Affine3& b)
{
    return {a.linear * b.linear, a.linear * b.translation + a.translation};
}

/// Σ_i weights[i]·transforms[i] taken entry by entry (the bracket of eq. 4.2 / 4.7): an
/// affine map again whenever the weights sum to 1.
[[nodiscard]] inline Affine3 weightedSum(const Affine3& accumulated, const Affine3& t, double weight)
{
    return {accumulated.linear + weight * t.linear, accumulated.translation + weight * t.translation};
}

} // namespace trimlab
