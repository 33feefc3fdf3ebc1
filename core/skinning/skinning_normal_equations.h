#pragma once
/// \file
/// Internal to core/animation (includes Eigen, which trimlab_core links privately; never
/// include it from a public header): normal equations whose unknowns are `blockSize`
/// values per bone and in which every vertex touches only its own ≤ 4 influences, so the
/// matrix has a block per pair of bones that share a vertex. Shared by the affine (LBS,
/// blocks of 4) and the rigid (DQS, blocks of 6) pose fits.

#include "core/skinning/skinning_fit_options.h"
#include "core/skinning/skinning_model.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace trimlab::detail {

/// The bone-pair pattern of a weight set: computed once, shared by every system.
struct BonePairPattern {
    std::size_t boneCount = 0;
    std::vector<std::array<std::uint32_t, 2>> pairs; ///< (lo, hi) bone pairs, lo ≤ hi
    std::vector<std::array<std::uint32_t, kMaxInfluences * kMaxInfluences>> vertexPairs; ///< [i·4+k] → pair index
};

[[nodiscard]] BonePairPattern bonePairPattern(const SkinningWeights& weights);

/// N = Σ JᵀJ and R = Σ Jᵀr over vertices, stored as bone-pair blocks.
class BoneBlockSystem {
public:
    BoneBlockSystem(const BonePairPattern& pattern, int blockSize, int rhsColumns);

    /// Adds vertex `vertex`: `jacobian` is rows × (count·blockSize), row-major, with the
    /// columns of influence i at [i·blockSize, (i+1)·blockSize); `residual` is rows ×
    /// rhsColumns, row-major.
    void addVertex(const VertexInfluences& influences, std::size_t vertex, int rows, const double* jacobian,
                   const double* residual);
    void add(const BoneBlockSystem& other);

    /// Solves (N + μ·diag(N) + λ·I)·X = R + λ·prior with λ = damping·(mean diagonal of N)
    /// (prior: B·blockSize × rhsColumns). The damping keeps bones without vertices, or with
    /// coplanar ones, at the prior instead of making N singular.
    [[nodiscard]] Eigen::MatrixXd solve(const Eigen::MatrixXd& prior, double damping, double mu,
                                        LinearSolverKind kind) const;
    [[nodiscard]] const Eigen::MatrixXd& rhs() const { return m_rhs; }

private:
    const BonePairPattern* m_pattern;
    int m_block;
    std::vector<double> m_blocks; ///< pairs × block × block, row-major per block
    Eigen::MatrixXd m_rhs;
};

/// Vertices [begin, end) of chunk `chunk` when #V vertices are cut into chunkCount(#V)
/// fixed chunks (independent of the thread count, so sums are deterministic).
[[nodiscard]] std::size_t chunkCount(std::size_t vertexCount);
[[nodiscard]] std::array<std::size_t, 2> chunkRange(std::size_t vertexCount, std::size_t chunk);

} // namespace trimlab::detail
