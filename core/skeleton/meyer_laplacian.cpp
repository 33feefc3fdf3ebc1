#include "core/skeleton/meyer_laplacian.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

bool isFinite(const glm::dvec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// What one triangle contributes: the edge weights ½cot of the opposite corner (edge k
// joins corners k+1 and k+2) and the mixed area of each corner.
struct TriangleTerms {
    std::array<double, 3> halfCot{};
    std::array<double, 3> area{};
    bool scaled = false;
};

// Mixed Voronoi areas of the corners (Meyer et al. 2003, section 3.3).
std::array<double, 3> mixedAreas(const std::array<glm::dvec3, 3>& p, const std::array<double, 3>& cot, double area)
{
    for (int k = 0; k < 3; ++k)
        if (cot[k] < 0.0) { // corner k is obtuse
            std::array<double, 3> result;
            result.fill(0.25 * area);
            result[k] = 0.5 * area;
            return result;
        }
    std::array<double, 3> result{};
    for (int k = 0; k < 3; ++k) {
        const int q = (k + 1) % 3, r = (k + 2) % 3;
        const glm::dvec3 pr = p[r] - p[k], pq = p[q] - p[k];
        result[k] = std::max(0.0, (glm::dot(pr, pr) * cot[q] + glm::dot(pq, pq) * cot[r]) / 8.0);
    }
    return result;
}

// The terms of one triangle; false when it contributes nothing (zero area, non-finite).
bool triangleTerms(const std::array<glm::dvec3, 3>& p, TriangleTerms& out)
{
    if (!isFinite(p[0]) || !isFinite(p[1]) || !isFinite(p[2]))
        return false;
    const double doubleArea = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    if (!(doubleArea > 0.0) || !std::isfinite(doubleArea))
        return false;
    std::array<double, 3> cot{};
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
        // |u × v| is twice the area at every corner; using the one value keeps the three
        // cotangents consistent (their pairwise products sum to 1).
        cot[k] = glm::dot(u, v) / doubleArea;
        largest = std::max(largest, std::abs(cot[k]));
    }
    out.area = mixedAreas(p, cot, 0.5 * doubleArea);
    const double scale = largest > kMaxCotangent ? kMaxCotangent / largest : 1.0;
    out.scaled = scale < 1.0;
    for (int k = 0; k < 3; ++k)
        out.halfCot[k] = 0.5 * scale * cot[k];
    return true;
}

// Sorts the per-triangle edge entries and adds up the duplicates (an interior edge is
// listed once by each of its two triangles).
std::vector<LaplacianEdge> mergedEdges(std::vector<LaplacianEdge> entries)
{
    std::sort(entries.begin(), entries.end(),
              [](const LaplacianEdge& a, const LaplacianEdge& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    std::vector<LaplacianEdge> merged;
    merged.reserve(entries.size() / 2 + 1);
    for (const LaplacianEdge& e : entries) {
        if (!merged.empty() && merged.back().i == e.i && merged.back().j == e.j)
            merged.back().weight += e.weight;
        else
            merged.push_back(e);
    }
    return merged;
}

} // namespace

MeyerLaplacian meyerLaplacian(std::span<const glm::dvec3> positions, std::span<const glm::uvec3> triangles)
{
    MeyerLaplacian result;
    result.diagonal.assign(positions.size(), 0.0);
    result.area.assign(positions.size(), 0.0);
    std::vector<LaplacianEdge> entries;
    entries.reserve(3 * triangles.size());
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const std::array<std::uint32_t, 3> v = {triangles[f].x, triangles[f].y, triangles[f].z};
        if (std::max({v[0], v[1], v[2]}) >= positions.size())
            throw std::out_of_range("meyerLaplacian: triangle " + std::to_string(f) + " names a vertex ≥ " +
                                    std::to_string(positions.size()));
        TriangleTerms terms;
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0] ||
            !triangleTerms({positions[v[0]], positions[v[1]], positions[v[2]]}, terms)) {
            ++result.skippedTriangles;
            continue;
        }
        result.scaledTriangles += terms.scaled ? 1 : 0;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = v[(k + 1) % 3], b = v[(k + 2) % 3];
            entries.push_back({std::min(a, b), std::max(a, b), terms.halfCot[k]});
            result.diagonal[a] += terms.halfCot[k];
            result.diagonal[b] += terms.halfCot[k];
            result.area[v[k]] += terms.area[k];
        }
    }
    result.edges = mergedEdges(std::move(entries));
    return result;
}

} // namespace trimlab
