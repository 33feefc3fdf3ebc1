#pragma once
/// \file
/// Rigid joint motions that make linear blend skinning match given positions — what a
/// glTF skin can play (skinning_gltf.h). For one pose it minimises
///     E = Σ_j ‖Σ_b w_bj (R_b v_j + t_b) − y_j‖²
/// over rotations R_b and translations t_b (rest positions v_j, weights w_bj, target y_j)
/// by block coordinate descent from a starting guess:
/// - translations, all bones together: linear least squares, the B×B normal matrix WᵀW
///   (factorised once per weights; λ = 10⁻⁹·trace(WᵀW)/B on its diagonal keeps bones no
///   vertex uses at their starting translation);
/// - one bone's rotation and translation together, bone by bone with the others fixed:
///   E restricted to bone b is Σ_j w_bj² ‖R_b v_j + t_b − r_j / w_bj‖² with r_j the target
///   minus the other bones' parts — weighted orthogonal Procrustes: with centroids
///   v̄ = Σ w² v / Σ w² and ȳ = Σ w r / Σ w², R_b is the closest rotation to
///   Σ_j (w r_j − w² ȳ)(v_j − v̄)ᵀ and t_b = ȳ − R_b v̄.
/// A sweep is every bone once, then the translations. Each step minimises E exactly in its
/// block (the translation step up to λ), so E does not grow; sweeps stop when it falls
/// by less than a relative 10⁻⁸ or after `sweeps`.
/// Starting from exact motions (E = 0) nothing changes.

#include "core/skinning/skinning_model.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace trimlab {

/// The rigid motion x ↦ rotation·x + translation of one joint at one pose (rest → pose,
/// in the model's space).
struct RigidJointPose {
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 translation{0.0};
};

/// The rotation closest to `m` in the Frobenius norm (polar decomposition U·Vᵀ of the
/// SVD; a reflection is turned into the nearest proper rotation).
[[nodiscard]] glm::dmat3 closestRotation(const glm::dmat3& m);

class RigidJointSolver {
public:
    /// `weights`: convex, one per rest position; `restPositions`: #V. Both must outlive
    /// the solver.
    RigidJointSolver(const SkinningWeights& weights, std::span<const glm::dvec3> restPositions);

    /// Improves `joints` (B motions; their values are the starting guess and the
    /// translations' tie-breaking prior) towards `target` (#V) and returns E afterwards.
    /// `sweeps` = 0 only solves the translations once.
    double solve(std::vector<RigidJointPose>& joints, std::span<const glm::dvec3> target, unsigned sweeps = 8) const;

private:
    void solveTranslations(std::vector<RigidJointPose>& joints, std::span<const glm::dvec3> target,
                           const std::vector<glm::dvec3>& prior) const;
    void solveBoneMotions(std::vector<RigidJointPose>& joints, std::span<const glm::dvec3> target) const;
    [[nodiscard]] std::vector<glm::dvec3> skinned(const std::vector<RigidJointPose>& joints) const;

    std::span<const glm::dvec3> m_rest;
    std::vector<std::vector<std::pair<std::uint32_t, double>>> m_boneVertices; ///< per bone (vertex, weight)
    struct NormalMatrix; ///< the LDLᵀ factor of WᵀW + λI (Eigen, kept out of this header)
    std::shared_ptr<const NormalMatrix> m_gram;
    double m_lambda = 0.0;
};

} // namespace trimlab
