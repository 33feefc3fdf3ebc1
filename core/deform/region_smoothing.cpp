#include "core/deform/region_smoothing.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

namespace trimlab::deform {

namespace {

// cot of the angle at `apex` between the rays to a and b; 0 for a degenerate corner
// (it then carries no weight instead of an infinite one).
double cotangent(const glm::dvec3& apex, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 u = a - apex, v = b - apex;
    const double sine = glm::length(glm::cross(u, v));
    return sine > 0.0 ? glm::dot(u, v) / sine : 0.0;
}

void uniformWeights(const RegionPatch& patch, std::vector<double>& w)
{
    for (std::size_t r = 0; r < patch.regionSize(); ++r) {
        const std::uint32_t begin = patch.ringOffset(r), end = patch.ringOffset(r + 1);
        for (std::uint32_t s = begin; s < end; ++s)
            w[s] = 1.0 / double(end - begin);
    }
}

void cotangentWeights(const RegionPatch& patch, std::span<const glm::dvec3> p, std::vector<double>& w)
{
    for (std::size_t r = 0; r < patch.regionSize(); ++r) {
        const std::uint32_t begin = patch.ringOffset(r), end = patch.ringOffset(r + 1);
        std::fill(w.begin() + begin, w.begin() + end, 0.0);
        for (const RegionPatch::Wedge& t : patch.wedges(r)) {
            // Edge r–j is opposite the corner at k, edge r–k opposite the corner at j.
            w[t.slotJ] += 0.5 * cotangent(p[t.k], p[r], p[t.j]);
            w[t.slotK] += 0.5 * cotangent(p[t.j], p[r], p[t.k]);
        }
        double sum = 0.0;
        for (std::uint32_t s = begin; s < end; ++s) {
            w[s] = std::max(w[s], 0.0);
            sum += w[s];
        }
        for (std::uint32_t s = begin; s < end; ++s)
            w[s] = sum > 0.0 ? w[s] / sum : 1.0 / double(end - begin);
    }
}

} // namespace

void smoothRegion(const RegionPatch& patch, std::span<glm::dvec3> positions, std::span<const double> steps,
                  SmoothingWeights weights, int iterations)
{
    std::vector<double> w(patch.ringSlotCount());
    std::vector<glm::dvec3> next(patch.regionSize());
    if (weights == SmoothingWeights::Uniform)
        uniformWeights(patch, w); // they do not depend on positions
    for (int it = 0; it < iterations; ++it) {
        if (weights == SmoothingWeights::Cotangent)
            cotangentWeights(patch, positions, w);
        for (std::size_t r = 0; r < patch.regionSize(); ++r) {
            glm::dvec3 laplacian(0.0);
            for (std::uint32_t s = patch.ringOffset(r); s < patch.ringOffset(r + 1); ++s)
                laplacian += w[s] * (positions[patch.ringNeighbour(s)] - positions[r]);
            next[r] = positions[r] + steps[r] * laplacian;
        }
        std::copy(next.begin(), next.end(), positions.begin());
    }
}

} // namespace trimlab::deform
