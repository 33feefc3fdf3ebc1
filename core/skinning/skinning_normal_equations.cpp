#include "core/skinning/skinning_normal_equations.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <map>
#include <stdexcept>

namespace trimlab::detail {

BonePairPattern bonePairPattern(const SkinningWeights& weights)
{
    BonePairPattern pattern;
    pattern.boneCount = weights.boneCount;
    std::map<std::array<std::uint32_t, 2>, std::uint32_t> index;
    for (std::uint32_t b = 0; b < weights.boneCount; ++b) // diagonal blocks always exist
        index.emplace(std::array<std::uint32_t, 2>{b, b}, 0);
    for (const VertexInfluences& in : weights.vertices)
        for (std::uint32_t i = 0; i < in.count; ++i)
            for (std::uint32_t k = 0; k < in.count; ++k)
                index.emplace(std::array<std::uint32_t, 2>{std::min(in.bones[i], in.bones[k]),
                                                           std::max(in.bones[i], in.bones[k])},
                              0);
    for (auto& [pair, i] : index) {
        i = std::uint32_t(pattern.pairs.size());
        pattern.pairs.push_back(pair);
    }
    pattern.vertexPairs.resize(weights.vertices.size());
    for (std::size_t v = 0; v < weights.vertices.size(); ++v) {
        const VertexInfluences& in = weights.vertices[v];
        for (std::uint32_t i = 0; i < in.count; ++i)
            for (std::uint32_t k = 0; k < in.count; ++k)
                pattern.vertexPairs[v][i * kMaxInfluences + k] =
                    index.at({std::min(in.bones[i], in.bones[k]), std::max(in.bones[i], in.bones[k])});
    }
    return pattern;
}

BoneBlockSystem::BoneBlockSystem(const BonePairPattern& pattern, int blockSize, int rhsColumns)
    : m_pattern(&pattern),
      m_block(blockSize),
      m_blocks(pattern.pairs.size() * std::size_t(blockSize * blockSize), 0.0),
      m_rhs(Eigen::MatrixXd::Zero(Eigen::Index(pattern.boneCount) * blockSize, rhsColumns))
{
}

void BoneBlockSystem::addVertex(const VertexInfluences& in, std::size_t vertex, int rows, const double* jacobian,
                                const double* residual)
{
    const int bs = m_block;
    const int width = int(in.count) * bs;
    const int rhsColumns = int(m_rhs.cols());
    for (std::uint32_t i = 0; i < in.count; ++i) {
        for (std::uint32_t k = 0; k < in.count; ++k) {
            // Only the (lo, hi) orientation is stored: the block of influence pair (i, k)
            // goes in as is when bone_i ≤ bone_k, and the mirrored pair supplies the rest.
            if (in.bones[i] > in.bones[k])
                continue;
            double* block =
                &m_blocks[std::size_t(m_pattern->vertexPairs[vertex][i * kMaxInfluences + k]) * std::size_t(bs * bs)];
            for (int r = 0; r < rows; ++r) {
                const double* row = jacobian + r * width;
                for (int p = 0; p < bs; ++p)
                    for (int q = 0; q < bs; ++q)
                        block[p * bs + q] += row[int(i) * bs + p] * row[int(k) * bs + q];
            }
        }
        for (int r = 0; r < rows; ++r)
            for (int p = 0; p < bs; ++p)
                for (int c = 0; c < rhsColumns; ++c)
                    m_rhs(Eigen::Index(in.bones[i]) * bs + p, c) +=
                        jacobian[r * width + int(i) * bs + p] * residual[r * rhsColumns + c];
    }
}

void BoneBlockSystem::add(const BoneBlockSystem& other)
{
    for (std::size_t i = 0; i < m_blocks.size(); ++i)
        m_blocks[i] += other.m_blocks[i];
    m_rhs += other.m_rhs;
}

namespace {

// Calls f(row, col, value) for every entry of the full symmetric matrix N.
template <class F>
void forEachEntry(const BonePairPattern& pattern, const std::vector<double>& blocks, int bs, F&& f)
{
    for (std::size_t k = 0; k < pattern.pairs.size(); ++k) {
        const auto [lo, hi] = pattern.pairs[k];
        const double* block = &blocks[k * std::size_t(bs * bs)];
        for (int p = 0; p < bs; ++p)
            for (int q = 0; q < bs; ++q) {
                const Eigen::Index row = Eigen::Index(lo) * bs + p;
                const Eigen::Index col = Eigen::Index(hi) * bs + q;
                f(row, col, block[p * bs + q]);
                if (lo != hi)
                    f(col, row, block[p * bs + q]);
            }
    }
}

} // namespace

Eigen::MatrixXd BoneBlockSystem::solve(const Eigen::MatrixXd& prior, double damping, double mu,
                                       LinearSolverKind kind) const
{
    const Eigen::Index n = m_rhs.rows();
    Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
    forEachEntry(*m_pattern, m_blocks, m_block, [&](Eigen::Index r, Eigen::Index c, double v) {
        if (r == c)
            diagonal(r) += v;
    });
    const double meanDiagonal = n > 0 ? std::max(diagonal.mean(), 1e-300) : 1.0;
    const double lambda = damping * meanDiagonal;
    const Eigen::MatrixXd rhs = m_rhs + lambda * prior;
    const bool dense = kind == LinearSolverKind::Dense || (kind == LinearSolverKind::Automatic && n <= 600);
    if (dense) {
        Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(n, n);
        forEachEntry(*m_pattern, m_blocks, m_block,
                     [&](Eigen::Index r, Eigen::Index c, double v) { matrix(r, c) += v; });
        matrix.diagonal() += mu * diagonal + Eigen::VectorXd::Constant(n, lambda);
        return matrix.ldlt().solve(rhs);
    }
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(m_blocks.size() * 2 + std::size_t(n));
    forEachEntry(*m_pattern, m_blocks, m_block,
                 [&](Eigen::Index r, Eigen::Index c, double v) { triplets.emplace_back(r, c, v); });
    for (Eigen::Index i = 0; i < n; ++i)
        triplets.emplace_back(i, i, mu * diagonal(i) + lambda);
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
    if (solver.info() != Eigen::Success)
        throw std::runtime_error("skinning fit: the normal equations could not be factored");
    return solver.solve(rhs);
}

std::size_t chunkCount(std::size_t vertexCount)
{
    return std::clamp<std::size_t>((vertexCount + 1023) / 1024, 1, 64);
}

std::array<std::size_t, 2> chunkRange(std::size_t vertexCount, std::size_t chunk)
{
    const std::size_t chunks = chunkCount(vertexCount);
    return {vertexCount * chunk / chunks, vertexCount * (chunk + 1) / chunks};
}

} // namespace trimlab::detail
