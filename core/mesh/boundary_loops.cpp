#include "core/mesh/boundary_loops.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace trimlab {

namespace {

/// One triangle side a → b, keyed by its undirected edge.
struct Side {
    std::uint32_t low = 0;
    std::uint32_t high = 0;
    std::uint32_t from = 0;
    std::uint32_t to = 0;
};

/// The hole's half-edges: each boundary side reversed, sorted by start vertex.
std::vector<Side> holeHalfEdges(std::span<const glm::uvec3> triangles)
{
    std::vector<Side> sides;
    sides.reserve(triangles.size() * 3);
    for (const glm::uvec3& t : triangles)
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t a = t[corner];
            const std::uint32_t b = t[(corner + 1) % 3];
            if (a != b)
                sides.push_back({std::min(a, b), std::max(a, b), a, b});
        }
    std::sort(sides.begin(), sides.end(),
              [](const Side& x, const Side& y) { return std::tie(x.low, x.high) < std::tie(y.low, y.high); });
    std::vector<Side> hole;
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t end = i + 1;
        while (end < sides.size() && sides[end].low == sides[i].low && sides[end].high == sides[i].high)
            ++end;
        if (end - i == 1)
            hole.push_back({sides[i].low, sides[i].high, sides[i].to, sides[i].from});
        i = end;
    }
    std::stable_sort(hole.begin(), hole.end(),
                     [](const Side& x, const Side& y) { return std::tie(x.from, x.to) < std::tie(y.from, y.to); });
    return hole;
}

/// The first unused half-edge leaving `vertex`, or hole.size().
std::size_t unusedFrom(const std::vector<Side>& hole, const std::vector<bool>& used, std::uint32_t vertex)
{
    auto it =
        std::lower_bound(hole.begin(), hole.end(), vertex, [](const Side& s, std::uint32_t v) { return s.from < v; });
    for (; it != hole.end() && it->from == vertex; ++it)
        if (!used[std::size_t(it - hole.begin())])
            return std::size_t(it - hole.begin());
    return hole.size();
}

} // namespace

std::vector<std::vector<std::uint32_t>> boundaryLoops(std::span<const glm::uvec3> triangles)
{
    const std::vector<Side> hole = holeHalfEdges(triangles);
    std::vector<bool> used(hole.size(), false);
    std::vector<std::vector<std::uint32_t>> loops;
    for (std::size_t start = 0; start < hole.size(); ++start) {
        if (used[start])
            continue;
        std::vector<std::uint32_t> loop;
        for (std::size_t edge = start;;) {
            used[edge] = true;
            loop.push_back(hole[edge].from);
            const std::uint32_t next = hole[edge].to;
            if (next == hole[start].from)
                break;
            edge = unusedFrom(hole, used, next);
            if (edge == hole.size())
                throw std::invalid_argument("the boundary edges do not form loops: vertex " + std::to_string(next) +
                                            " has more boundary edges into it than out of it (inconsistent "
                                            "orientation?)");
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

} // namespace trimlab
