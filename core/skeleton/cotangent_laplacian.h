#pragma once
/// \file
/// The cotangent Laplacian of Berenguer & Moreno eq. (1) (Desbrun et al.), rebuilt every
/// contraction iteration on a sparsity pattern that the connectivity fixes once, so that
/// the normal equations keep one pattern and their symbolic analysis runs only once.
/// Internal to core/skeleton (exposes Eigen types; trimlab_core links Eigen privately).

#include <Eigen/SparseCore>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace trimlab {

using SkeletonSparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// The cotangent cot(θ) of the angle at `corner` between the edges to `a` and `b`,
/// clamped to [−maxCotangent, maxCotangent], i.e. θ clamped to [θmin, 180° − θmin] with
/// cot θmin = maxCotangent. Collinear corners give ±maxCotangent (the sign of the
/// angle's cosine: 0° or 180°); a corner that coincides with a or b (0/0, no angle at
/// all) gives +maxCotangent, a collapsed corner being the limit of a tiny angle. Never
/// NaN or infinite for finite input.
[[nodiscard]] double clampedCotangent(const glm::dvec3& corner, const glm::dvec3& a, const glm::dvec3& b,
                                      double maxCotangent);

/// L (#V×#V, symmetric): L_ij = ω_ij = max(0, cot α_ij + cot β_ij) for every mesh edge
/// (i, j), L_ii = −Σ_j ω_ij, 0 elsewhere; each cotangent clamped by clampedCotangent. The
/// floor at 0 keeps L an averaging operator on obtuse configurations (see update()). The pattern
/// holds every edge and every diagonal entry (also of vertices no triangle uses, whose
/// row stays 0) and never changes; update() rewrites the values only.
class CotangentLaplacian {
public:
    /// Pattern from `triangles` (indices < vertexCount, no repeated index in a face).
    CotangentLaplacian(std::size_t vertexCount, std::span<const glm::uvec3> triangles);

    /// Values from `positions` (#V). O(F).
    void update(std::span<const glm::dvec3> positions, double maxCotangent);

    [[nodiscard]] const SkeletonSparseMatrix& matrix() const { return m_matrix; }

private:
    std::vector<glm::uvec3> m_triangles;
    std::vector<int> m_sideEdge;             // per triangle side (3 per face, opposite corner c): its edge
    std::vector<std::array<int, 4>> m_slots; // per edge (a, b): the value slots of L_ab, L_ba, L_aa, L_bb
    std::vector<double> m_edgeWeights;       // scratch: ω per edge
    SkeletonSparseMatrix m_matrix;
};

} // namespace trimlab
