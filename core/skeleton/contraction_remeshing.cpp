#include "core/skeleton/contraction_remeshing.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <iterator>
#include <tuple>
#include <utility>

namespace trimlab {

namespace {

class TriangleSoupEditor {
public:
    TriangleSoupEditor(std::span<const glm::dvec3> positions, std::span<const glm::uvec3> triangles)
        : m_positions(positions.begin(), positions.end()),
          m_triangles(triangles.begin(), triangles.end()),
          m_triangleAlive(triangles.size(), 1),
          m_vertexTriangles(positions.size()),
          m_alive(positions.size(), 1)
    {
        for (std::size_t t = 0; t < m_triangles.size(); ++t)
            for (int c = 0; c < 3; ++c)
                m_vertexTriangles[m_triangles[t][c]].push_back(static_cast<int>(t));
    }

    [[nodiscard]] bool alive(std::uint32_t v) const { return m_alive[v] != 0; }
    [[nodiscard]] double length(std::uint32_t a, std::uint32_t b) const
    {
        return glm::length(m_positions[a] - m_positions[b]);
    }

    // Collapses b into a at the midpoint when the link condition holds; see the header.
    bool tryCollapse(std::uint32_t a, std::uint32_t b)
    {
        std::array<int, 2> shared{-1, -1};
        int sharedCount = 0;
        for (int t : m_vertexTriangles[a])
            if (contains(t, b)) {
                if (sharedCount == 2)
                    return false; // a non-manifold edge: leave it
                shared[static_cast<std::size_t>(sharedCount++)] = t;
            }
        if (sharedCount != 2)
            return false;
        const std::uint32_t c = opposite(shared[0], a, b);
        const std::uint32_t d = opposite(shared[1], a, b);
        if (c == d || neighbourCount(c) <= 3 || neighbourCount(d) <= 3)
            return false;
        std::vector<std::uint32_t> around = neighbours(a);
        const std::vector<std::uint32_t> aroundB = neighbours(b);
        std::vector<std::uint32_t> common;
        std::set_intersection(around.begin(), around.end(), aroundB.begin(), aroundB.end(), std::back_inserter(common));
        if (common.size() != 2)
            return false; // a and b are joined around a handle or a thin neck: collapsing would pinch it
        for (int t : shared)
            m_triangleAlive[static_cast<std::size_t>(t)] = 0;
        for (int t : m_vertexTriangles[b]) {
            if (!m_triangleAlive[static_cast<std::size_t>(t)])
                continue;
            for (int k = 0; k < 3; ++k)
                if (m_triangles[static_cast<std::size_t>(t)][k] == b)
                    m_triangles[static_cast<std::size_t>(t)][k] = a;
            m_vertexTriangles[a].push_back(t);
        }
        m_vertexTriangles[b].clear();
        std::erase_if(m_vertexTriangles[a], [&](int t) { return !m_triangleAlive[static_cast<std::size_t>(t)]; });
        m_positions[a] = 0.5 * (m_positions[a] + m_positions[b]);
        m_alive[b] = 0;
        m_absorbedBy.emplace_back(b, a);
        return true;
    }

    [[nodiscard]] CollapsedMesh result(std::size_t collapses) const
    {
        CollapsedMesh out;
        out.collapses = collapses;
        const std::size_t n = m_positions.size();
        std::vector<int> index(n, -1);
        for (std::size_t v = 0; v < n; ++v)
            if (m_alive[v]) {
                index[v] = static_cast<int>(out.positions.size());
                out.positions.push_back(m_positions[v]);
            }
        // Dead vertices point at their absorber, which may have died later: resolve in
        // reverse collapse order so every absorber is final when read.
        out.newIndex = index;
        for (auto it = m_absorbedBy.rbegin(); it != m_absorbedBy.rend(); ++it)
            out.newIndex[it->first] = out.newIndex[it->second];
        for (std::size_t t = 0; t < m_triangles.size(); ++t)
            if (m_triangleAlive[t]) {
                const glm::uvec3& tri = m_triangles[t];
                out.triangles.emplace_back(index[tri[0]], index[tri[1]], index[tri[2]]);
            }
        return out;
    }

private:
    [[nodiscard]] bool contains(int t, std::uint32_t v) const
    {
        const glm::uvec3& tri = m_triangles[static_cast<std::size_t>(t)];
        return m_triangleAlive[static_cast<std::size_t>(t)] && (tri[0] == v || tri[1] == v || tri[2] == v);
    }
    [[nodiscard]] std::uint32_t opposite(int t, std::uint32_t a, std::uint32_t b) const
    {
        const glm::uvec3& tri = m_triangles[static_cast<std::size_t>(t)];
        for (int k = 0; k < 3; ++k)
            if (tri[k] != a && tri[k] != b)
                return tri[k];
        return a;
    }
    // Sorted, without duplicates.
    [[nodiscard]] std::vector<std::uint32_t> neighbours(std::uint32_t v) const
    {
        std::vector<std::uint32_t> out;
        for (int t : m_vertexTriangles[v]) {
            if (!m_triangleAlive[static_cast<std::size_t>(t)])
                continue;
            for (int k = 0; k < 3; ++k)
                if (const std::uint32_t u = m_triangles[static_cast<std::size_t>(t)][k]; u != v)
                    out.push_back(u);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }
    [[nodiscard]] std::size_t neighbourCount(std::uint32_t v) const { return neighbours(v).size(); }

    std::vector<glm::dvec3> m_positions;
    std::vector<glm::uvec3> m_triangles;
    std::vector<char> m_triangleAlive;
    std::vector<std::vector<int>> m_vertexTriangles;
    std::vector<char> m_alive;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> m_absorbedBy; // (dead, absorber), in collapse order
};

} // namespace

CollapsedMesh collapseShortEdges(std::span<const glm::dvec3> positions, std::span<const glm::uvec3> triangles,
                                 double minLength)
{
    std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> shortEdges;
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k];
            const std::uint32_t b = t[(k + 1) % 3];
            if (a < b) // each interior edge once (the other triangle lists it as b → a)
                if (const double l = glm::length(positions[a] - positions[b]); l < minLength)
                    shortEdges.emplace_back(l, a, b);
        }
    TriangleSoupEditor editor(positions, triangles);
    if (shortEdges.empty())
        return editor.result(0);
    std::sort(shortEdges.begin(), shortEdges.end());
    std::size_t collapses = 0;
    for (const auto& [l, a, b] : shortEdges) {
        if (!editor.alive(a) || !editor.alive(b) || editor.length(a, b) >= minLength)
            continue;
        if (editor.tryCollapse(a, b))
            ++collapses;
    }
    return editor.result(collapses);
}

} // namespace trimlab
