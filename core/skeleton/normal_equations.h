#pragma once
/// \file
/// The least-squares system of geometry contraction (Berenguer & Moreno eqs. 2–5):
/// A = [W_L·L; W_H] (2#V×#V), B = [0; W_H·V], solved through AᵀA·V' = AᵀB. With
/// diagonal W_L, W_H and a symmetric L, AᵀA = L·W_L²·L + W_H², whose pattern (the
/// two-ring of every vertex) the connectivity fixes: it is built once and only the
/// values are refreshed per iteration. Internal to core/skeleton (Eigen types).

#include "core/skeleton/cotangent_laplacian.h"

#include <Eigen/Core>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace trimlab {

class NormalEquations {
public:
    /// The pattern of the lower triangle of L² (and of A, for COLAMD) from L's pattern.
    explicit NormalEquations(const SkeletonSparseMatrix& laplacian);

    /// Lower triangle of L·diag(W_L²)·L + diag(W_H²) with L = `laplacian` (same pattern
    /// as the constructor's, symmetric values) and #V weights each.
    /// O(Σ_j Σ_{k∈N(j)} |N(k)|).
    void update(const SkeletonSparseMatrix& laplacian, std::span<const double> contractionWeights,
                std::span<const double> attractionWeights);

    /// AᵀB = W_H²·V (#V×3).
    [[nodiscard]] static Eigen::MatrixX3d rightHandSide(std::span<const glm::dvec3> positions,
                                                        std::span<const double> attractionWeights);

    [[nodiscard]] const SkeletonSparseMatrix& lower() const { return m_lower; }
    /// The pattern of A = [L; I] (2#V×#V, values 1), for the COLAMD ordering.
    [[nodiscard]] SkeletonSparseMatrix stackedPattern(const SkeletonSparseMatrix& laplacian) const;

private:
    SkeletonSparseMatrix m_lower;
    std::vector<int> m_slot; // scratch: value index of row i in the current column, or −1
};

} // namespace trimlab
