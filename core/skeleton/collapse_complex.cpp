#include "core/skeleton/collapse_complex.h"

#include <algorithm>

namespace trimlab {

CollapseComplex::CollapseComplex(std::span<const glm::dvec3> positions, std::span<const glm::uvec3> triangles)
    : m_positions(positions.begin(), positions.end()),
      m_triangleAlive(triangles.size(), 1),
      m_vertexTriangles(positions.size()),
      m_neighbours(positions.size()),
      m_alive(positions.size(), 1),
      m_absorbedBy(positions.size(), -1),
      m_liveTriangles(triangles.size()),
      m_liveVertices(positions.size())
{
    m_triangles.reserve(triangles.size());
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const glm::uvec3 t = triangles[f];
        m_triangles.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
        for (int c = 0; c < 3; ++c) {
            m_vertexTriangles[t[c]].push_back(static_cast<int>(f));
            m_neighbours[t[c]].push_back(static_cast<int>(t[(c + 1) % 3]));
            m_neighbours[t[c]].push_back(static_cast<int>(t[(c + 2) % 3]));
        }
    }
    for (std::vector<int>& list : m_neighbours) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
}

bool CollapseComplex::edgeHasTriangle(int a, int b) const
{
    for (int f : m_vertexTriangles[static_cast<std::size_t>(a)]) {
        if (!m_triangleAlive[static_cast<std::size_t>(f)])
            continue;
        const std::array<int, 3>& t = m_triangles[static_cast<std::size_t>(f)];
        if (t[0] == b || t[1] == b || t[2] == b)
            return true;
    }
    return false;
}

void CollapseComplex::removeNeighbour(int v, int gone)
{
    std::vector<int>& list = m_neighbours[static_cast<std::size_t>(v)];
    list.erase(std::remove(list.begin(), list.end(), gone), list.end());
}

void CollapseComplex::addNeighbour(int v, int other)
{
    std::vector<int>& list = m_neighbours[static_cast<std::size_t>(v)];
    if (std::find(list.begin(), list.end(), other) == list.end())
        list.push_back(other);
}

void CollapseComplex::dropDeadTriangles(int v)
{
    std::vector<int>& list = m_vertexTriangles[static_cast<std::size_t>(v)];
    list.erase(
        std::remove_if(list.begin(), list.end(), [&](int f) { return !m_triangleAlive[static_cast<std::size_t>(f)]; }),
        list.end());
}

void CollapseComplex::collapse(int from, int to)
{
    const auto fromIndex = static_cast<std::size_t>(from);
    for (int f : m_vertexTriangles[fromIndex]) {
        const auto fi = static_cast<std::size_t>(f);
        if (!m_triangleAlive[fi])
            continue;
        std::array<int, 3>& t = m_triangles[fi];
        if (t[0] == to || t[1] == to || t[2] == to) {
            m_triangleAlive[fi] = 0; // loses its corner `from`: degenerate
            --m_liveTriangles;
            continue;
        }
        std::replace(t.begin(), t.end(), from, to);
        m_vertexTriangles[static_cast<std::size_t>(to)].push_back(f);
    }
    m_vertexTriangles[fromIndex].clear();
    m_vertexTriangles[fromIndex].shrink_to_fit();
    for (int k : m_neighbours[fromIndex]) {
        removeNeighbour(k, from);
        if (k == to)
            continue;
        addNeighbour(k, to);
        addNeighbour(to, k);
    }
    m_neighbours[fromIndex].clear();
    m_neighbours[fromIndex].shrink_to_fit();
    dropDeadTriangles(to);
    for (int k : m_neighbours[static_cast<std::size_t>(to)])
        dropDeadTriangles(k);
    m_alive[fromIndex] = 0;
    m_absorbedBy[fromIndex] = to;
    --m_liveVertices;
}

int CollapseComplex::representative(int v)
{
    int root = v;
    while (m_absorbedBy[static_cast<std::size_t>(root)] >= 0)
        root = m_absorbedBy[static_cast<std::size_t>(root)];
    while (m_absorbedBy[static_cast<std::size_t>(v)] >= 0) { // path compression
        const int next = m_absorbedBy[static_cast<std::size_t>(v)];
        m_absorbedBy[static_cast<std::size_t>(v)] = root;
        v = next;
    }
    return root;
}

} // namespace trimlab
