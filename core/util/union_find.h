#pragma once
/// \file
/// Disjoint sets over 0..n-1 (union-find with path halving): connected components of
/// mesh faces, face sides of the trimmed solid's cells, coplanar groups of triangles.

#include <cstddef>
#include <numeric>
#include <vector>

namespace trimlab {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }

    /// The representative of `i`'s set.
    std::size_t find(std::size_t i)
    {
        while (m_parent[i] != i) {
            m_parent[i] = m_parent[m_parent[i]]; // path halving keeps later finds short
            i = m_parent[i];
        }
        return i;
    }
    void unite(std::size_t a, std::size_t b) { m_parent[find(a)] = find(b); }

private:
    std::vector<std::size_t> m_parent;
};

} // namespace trimlab
