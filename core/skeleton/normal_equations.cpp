#include "core/skeleton/normal_equations.h"

#include <algorithm>

namespace trimlab {

NormalEquations::NormalEquations(const SkeletonSparseMatrix& laplacian)
{
    const int n = static_cast<int>(laplacian.cols());
    const int* outer = laplacian.outerIndexPtr();
    const int* inner = laplacian.innerIndexPtr();
    std::vector<int> mark(static_cast<std::size_t>(n), -1);
    std::vector<int> starts(static_cast<std::size_t>(n) + 1, 0);
    std::vector<int> rows;
    std::vector<int> column;
    // Column j of L² has a row i ≥ j wherever some k links i–k–j (L symmetric).
    for (int j = 0; j < n; ++j) {
        column.clear();
        for (int p = outer[j]; p < outer[j + 1]; ++p)
            for (int k = inner[p], q = outer[k]; q < outer[k + 1]; ++q)
                if (const int i = inner[q]; i >= j && mark[i] != j) {
                    mark[i] = j;
                    column.push_back(i);
                }
        if (mark[j] != j)
            column.push_back(j); // the diagonal always exists (W_H² > 0)
        std::sort(column.begin(), column.end());
        rows.insert(rows.end(), column.begin(), column.end());
        starts[j + 1] = static_cast<int>(rows.size());
    }
    m_lower.resize(n, n);
    m_lower.resizeNonZeros(static_cast<Eigen::Index>(rows.size()));
    std::copy(starts.begin(), starts.end(), m_lower.outerIndexPtr());
    std::copy(rows.begin(), rows.end(), m_lower.innerIndexPtr());
    std::fill(m_lower.valuePtr(), m_lower.valuePtr() + rows.size(), 0.0);
    m_slot.assign(static_cast<std::size_t>(n), -1);
}

void NormalEquations::update(const SkeletonSparseMatrix& laplacian, std::span<const double> contractionWeights,
                             std::span<const double> attractionWeights)
{
    const int n = static_cast<int>(m_lower.cols());
    const int* outer = laplacian.outerIndexPtr();
    const int* inner = laplacian.innerIndexPtr();
    const double* value = laplacian.valuePtr();
    const int* lowerOuter = m_lower.outerIndexPtr();
    const int* lowerInner = m_lower.innerIndexPtr();
    double* lowerValue = m_lower.valuePtr();
    for (int j = 0; j < n; ++j) {
        for (int s = lowerOuter[j]; s < lowerOuter[j + 1]; ++s) {
            m_slot[lowerInner[s]] = s;
            lowerValue[s] = 0.0;
        }
        // (L·W_L²·L)_ij = Σ_k L_ik·w_k²·L_kj, with L_ik read from column k (L symmetric).
        for (int p = outer[j]; p < outer[j + 1]; ++p) {
            const int k = inner[p];
            const double wk = contractionWeights[static_cast<std::size_t>(k)];
            const double lkj = wk * wk * value[p];
            for (int q = outer[k]; q < outer[k + 1]; ++q)
                if (const int i = inner[q]; i >= j)
                    lowerValue[m_slot[i]] += value[q] * lkj;
        }
        const double wh = attractionWeights[static_cast<std::size_t>(j)];
        lowerValue[m_slot[j]] += wh * wh;
    }
}

Eigen::MatrixX3d NormalEquations::rightHandSide(std::span<const glm::dvec3> positions,
                                                std::span<const double> attractionWeights)
{
    Eigen::MatrixX3d rhs(static_cast<Eigen::Index>(positions.size()), 3);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const double w2 = attractionWeights[i] * attractionWeights[i];
        for (int c = 0; c < 3; ++c)
            rhs(static_cast<Eigen::Index>(i), c) = w2 * positions[i][c];
    }
    return rhs;
}

SkeletonSparseMatrix NormalEquations::stackedPattern(const SkeletonSparseMatrix& laplacian) const
{
    const int n = static_cast<int>(laplacian.cols());
    std::vector<Eigen::Triplet<double, int>> entries;
    entries.reserve(static_cast<std::size_t>(laplacian.nonZeros()) + static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
        for (SkeletonSparseMatrix::InnerIterator it(laplacian, j); it; ++it)
            entries.emplace_back(static_cast<int>(it.row()), j, 1.0);
        entries.emplace_back(n + j, j, 1.0);
    }
    SkeletonSparseMatrix stacked(2 * n, n);
    stacked.setFromTriplets(entries.begin(), entries.end());
    stacked.makeCompressed();
    return stacked;
}

} // namespace trimlab
