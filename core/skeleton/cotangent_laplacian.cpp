#include "core/skeleton/cotangent_laplacian.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace trimlab {

double clampedCotangent(const glm::dvec3& corner, const glm::dvec3& a, const glm::dvec3& b, double maxCotangent)
{
    const glm::dvec3 u = a - corner;
    const glm::dvec3 w = b - corner;
    const double cosine = glm::dot(u, w);              // |u||w| cos θ
    const double sine = glm::length(glm::cross(u, w)); // |u||w| sin θ ≥ 0
    if (!(sine > 0.0) || !std::isfinite(sine))
        return cosine < 0.0 ? -maxCotangent : maxCotangent;
    return std::clamp(cosine / sine, -maxCotangent, maxCotangent);
}

CotangentLaplacian::CotangentLaplacian(std::size_t vertexCount, std::span<const glm::uvec3> triangles)
    : m_triangles(triangles.begin(), triangles.end())
{
    const int n = static_cast<int>(vertexCount);
    std::vector<Eigen::Triplet<double, int>> pattern;
    pattern.reserve(6 * triangles.size() + vertexCount);
    for (int i = 0; i < n; ++i)
        pattern.emplace_back(i, i, 0.0);
    for (const glm::uvec3& t : triangles)
        for (int c = 0; c < 3; ++c) {
            const int a = static_cast<int>(t[(c + 1) % 3]), b = static_cast<int>(t[(c + 2) % 3]);
            pattern.emplace_back(a, b, 0.0);
            pattern.emplace_back(b, a, 0.0);
        }
    m_matrix.resize(n, n);
    m_matrix.setFromTriplets(pattern.begin(), pattern.end()); // duplicates merge; zeros stay structural
    m_matrix.makeCompressed();

    // Value index of (row, col): binary search in the column's sorted row indices.
    const auto slot = [&](int row, int col) {
        const int* begin = m_matrix.innerIndexPtr() + m_matrix.outerIndexPtr()[col];
        const int* end = m_matrix.innerIndexPtr() + m_matrix.outerIndexPtr()[col + 1];
        return static_cast<int>(std::lower_bound(begin, end, row) - m_matrix.innerIndexPtr());
    };
    // Edges (a < b) numbered in column order of the upper triangle, so each side finds
    // its edge by the slot of L_ab.
    std::vector<int> edgeOfSlot(static_cast<std::size_t>(m_matrix.nonZeros()), -1);
    for (int col = 0; col < n; ++col)
        for (int p = m_matrix.outerIndexPtr()[col]; p < m_matrix.outerIndexPtr()[col + 1]; ++p)
            if (const int row = m_matrix.innerIndexPtr()[p]; row < col) {
                edgeOfSlot[static_cast<std::size_t>(p)] = static_cast<int>(m_slots.size());
                m_slots.push_back({p, slot(col, row), slot(row, row), slot(col, col)});
            }
    m_sideEdge.reserve(3 * triangles.size());
    for (const glm::uvec3& t : triangles)
        for (int c = 0; c < 3; ++c) {
            const int a = static_cast<int>(t[(c + 1) % 3]), b = static_cast<int>(t[(c + 2) % 3]);
            m_sideEdge.push_back(edgeOfSlot[static_cast<std::size_t>(slot(std::min(a, b), std::max(a, b)))]);
        }
    m_edgeWeights.resize(m_slots.size());
}

void CotangentLaplacian::update(std::span<const glm::dvec3> positions, double maxCotangent)
{
    std::fill(m_edgeWeights.begin(), m_edgeWeights.end(), 0.0);
    std::size_t side = 0;
    for (const glm::uvec3& t : m_triangles)
        for (int c = 0; c < 3; ++c, ++side)
            m_edgeWeights[static_cast<std::size_t>(m_sideEdge[side])] +=
                clampedCotangent(positions[t[c]], positions[t[(c + 1) % 3]], positions[t[(c + 2) % 3]], maxCotangent);
    double* values = m_matrix.valuePtr();
    std::fill(values, values + m_matrix.nonZeros(), 0.0);
    for (std::size_t e = 0; e < m_slots.size(); ++e) {
        // An edge whose two opposite angles sum past 180° has a negative cotangent weight:
        // L then no longer averages a vertex's neighbours, and with W_L in the hundreds
        // L·V' ≈ 0 admits webs far from the surface (the area rises, the contraction has to
        // stop early). Such an edge gets weight 0 instead, which lets the contraction go
        // further and keeps more of the curve skeleton inside, in less time
        // (docs/measurements/2026-11-29-skeleton-stages.md).
        const double w = std::max(0.0, m_edgeWeights[e]);
        const std::array<int, 4>& s = m_slots[e];
        values[s[0]] += w;
        values[s[1]] += w;
        values[s[2]] -= w;
        values[s[3]] -= w;
    }
}

} // namespace trimlab
