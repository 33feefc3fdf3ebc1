#include "core/skeleton/body_root.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace trimlab {

namespace {

// A pair of limbs whose lighter member holds less than this share of the vertices does
// not make a pelvis (ears, fingers).
constexpr double kLimbPairShare = 0.04;

// The mass of each part the graph falls into without `removed`, heaviest first.
std::vector<std::size_t> partsWithout(int removed, const std::vector<std::vector<int>>& adjacent,
                                      std::span<const std::size_t> mass)
{
    std::vector<char> seen(adjacent.size(), 0);
    seen[static_cast<std::size_t>(removed)] = 1;
    std::vector<std::size_t> parts;
    for (int start : adjacent[static_cast<std::size_t>(removed)]) {
        if (seen[static_cast<std::size_t>(start)])
            continue;
        std::size_t total = 0;
        std::vector<int> stack{start};
        seen[static_cast<std::size_t>(start)] = 1;
        while (!stack.empty()) {
            const auto k = static_cast<std::size_t>(stack.back());
            stack.pop_back();
            total += mass[k];
            for (int next : adjacent[k])
                if (!seen[static_cast<std::size_t>(next)]) {
                    seen[static_cast<std::size_t>(next)] = 1;
                    stack.push_back(next);
                }
        }
        parts.push_back(total);
    }
    std::sort(parts.rbegin(), parts.rend());
    return parts;
}

} // namespace

int bodyRoot(const std::vector<std::vector<int>>& adjacent, std::span<const std::size_t> mass)
{
    if (adjacent.size() != mass.size())
        throw std::invalid_argument("bodyRoot: " + std::to_string(mass.size()) + " masses for " +
                                    std::to_string(adjacent.size()) + " nodes");
    std::size_t total = 0;
    for (std::size_t m : mass)
        total += m;
    int pelvis = -1, centre = -1, hub = -1;
    std::size_t pelvisBody = 0;
    std::size_t centreLargest = std::numeric_limits<std::size_t>::max(), hubLargest = centreLargest;
    for (int k = 0; k < static_cast<int>(adjacent.size()); ++k) {
        const std::vector<std::size_t> parts = partsWithout(k, adjacent, mass);
        const std::size_t largest = parts.empty() ? 0 : parts.front();
        const bool pair = parts.size() >= 3 &&
                          static_cast<double>(parts[2]) >= kLimbPairShare * static_cast<double>(total) &&
                          static_cast<double>(parts[2]) >= kLikeLimbs * static_cast<double>(parts[1]);
        if (pair && largest > pelvisBody) {
            pelvisBody = largest;
            pelvis = k;
        }
        if (parts.size() >= 3 && largest < hubLargest) {
            hubLargest = largest;
            hub = k;
        }
        if (largest < centreLargest) {
            centreLargest = largest;
            centre = k;
        }
    }
    return pelvis >= 0 ? pelvis : hub >= 0 ? hub : std::max(centre, 0);
}

} // namespace trimlab
