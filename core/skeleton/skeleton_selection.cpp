#include "core/skeleton/skeleton_selection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace trimlab {

namespace {

// A branch whose region holds fewer vertices than this fraction of its junction's region
// is a few stray vertices (left dangling when the triangles around them collapsed), not
// an arm: a real arm absorbs a whole tip and every cross-section along it.
constexpr double kSpuriousRegionFraction = 0.1;

// The curve skeleton as a mutable graph whose collapses merge regions.
class NodeGraph {
public:
    NodeGraph(const CurveSkeleton& curve, std::span<const glm::dvec3> originalPositions, const PointInMesh* solid);

    [[nodiscard]] int degree(int k) const { return static_cast<int>(m_adjacent[static_cast<std::size_t>(k)].size()); }
    [[nodiscard]] std::size_t aliveCount() const { return m_aliveCount; }
    std::size_t pruneSpuriousBranches();
    std::size_t mergeNearbyJunctions();
    bool collapseShortest();
    [[nodiscard]] NodeSelection result() const;

private:
    [[nodiscard]] double length(int a, int b) const
    {
        return glm::length(m_positions[static_cast<std::size_t>(a)] - m_positions[static_cast<std::size_t>(b)]);
    }
    [[nodiscard]] bool eligible(int a, int b) const;
    [[nodiscard]] int survivor(int a, int b) const;
    [[nodiscard]] bool mergeStaysInside(int loser, int survivor);
    [[nodiscard]] bool segmentInside(int a, int b);
    bool pruneBranchFrom(int leaf);
    void merge(int loser, int survivor);
    [[nodiscard]] int find(int k) const;

    std::vector<glm::dvec3> m_positions;
    std::vector<std::vector<int>> m_adjacent;
    std::vector<std::size_t> m_regionSize;
    std::vector<double> m_radius;    // mean distance from the node to its region's original vertices
    std::vector<double> m_clearance; // distance from the node to the nearest original vertex (junctions only)
    std::vector<std::size_t> m_curveRegionSize; // region sizes before any merge
    std::vector<int> m_absorbedBy;              // −1 while alive
    std::size_t m_aliveCount = 0;
    const PointInMesh* m_solid = nullptr;
    std::map<std::pair<int, int>, bool> m_segmentInside; // positions never change: test each pair once
};

NodeGraph::NodeGraph(const CurveSkeleton& curve, std::span<const glm::dvec3> originalPositions,
                     const PointInMesh* solid)
    : m_positions(curve.nodes),
      m_adjacent(curve.nodes.size()),
      m_regionSize(curve.nodes.size(), 0),
      m_radius(curve.nodes.size(), 0.0),
      m_absorbedBy(curve.nodes.size(), -1),
      m_aliveCount(curve.nodes.size()),
      m_solid(solid)
{
    const auto n = static_cast<int>(curve.nodes.size());
    for (const std::array<int, 2>& e : curve.edges) {
        if (e[0] < 0 || e[1] < 0 || e[0] >= n || e[1] >= n)
            throw std::invalid_argument("selectSkeletonNodes: edge (" + std::to_string(e[0]) + ", " +
                                        std::to_string(e[1]) + ") is out of range for " + std::to_string(n) + " nodes");
        if (e[0] == e[1])
            continue;
        m_adjacent[static_cast<std::size_t>(e[0])].push_back(e[1]);
        m_adjacent[static_cast<std::size_t>(e[1])].push_back(e[0]);
    }
    for (std::vector<int>& list : m_adjacent) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    for (std::size_t v = 0; v < originalPositions.size(); ++v) {
        const int k = curve.vertexNode[v];
        if (k < 0 || k >= n)
            throw std::invalid_argument("selectSkeletonNodes: vertex " + std::to_string(v) + " maps to node " +
                                        std::to_string(k) + " of " + std::to_string(n));
        ++m_regionSize[static_cast<std::size_t>(k)];
        m_radius[static_cast<std::size_t>(k)] +=
            glm::length(originalPositions[v] - m_positions[static_cast<std::size_t>(k)]);
    }
    for (std::size_t k = 0; k < m_radius.size(); ++k)
        if (m_regionSize[k] > 0)
            m_radius[k] /= static_cast<double>(m_regionSize[k]);
    m_curveRegionSize = m_regionSize;
    m_clearance.assign(curve.nodes.size(), 0.0);
    for (std::size_t k = 0; k < curve.nodes.size(); ++k) {
        if (m_adjacent[k].size() < 3)
            continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (const glm::dvec3& p : originalPositions)
            nearest = std::min(nearest, glm::length(p - m_positions[k]));
        m_clearance[k] = std::isfinite(nearest) ? nearest : 0.0;
    }
}

bool NodeGraph::segmentInside(int a, int b)
{
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    if (const auto known = m_segmentInside.find(key); known != m_segmentInside.end())
        return known->second;
    const bool inside = m_solid->segmentInside(m_positions[static_cast<std::size_t>(key.first)],
                                               m_positions[static_cast<std::size_t>(key.second)]);
    m_segmentInside.emplace(key, inside);
    return inside;
}

// Whether every edge `survivor` would gain from absorbing `loser` stays inside the solid.
// An edge that already left before (the refinement could not place a node inside) does
// not block: only new ones count.
bool NodeGraph::mergeStaysInside(int loser, int survivor)
{
    if (m_solid == nullptr)
        return true;
    const std::vector<int>& kept = m_adjacent[static_cast<std::size_t>(survivor)];
    for (int k : m_adjacent[static_cast<std::size_t>(loser)])
        if (k != survivor && std::find(kept.begin(), kept.end(), k) == kept.end() && !segmentInside(survivor, k))
            return false;
    return true;
}

int NodeGraph::find(int k) const
{
    while (m_absorbedBy[static_cast<std::size_t>(k)] >= 0)
        k = m_absorbedBy[static_cast<std::size_t>(k)];
    return k;
}

void NodeGraph::merge(int loser, int survivor)
{
    for (int k : m_adjacent[static_cast<std::size_t>(loser)]) {
        std::vector<int>& around = m_adjacent[static_cast<std::size_t>(k)];
        around.erase(std::remove(around.begin(), around.end(), loser), around.end());
        if (k == survivor)
            continue;
        if (std::find(around.begin(), around.end(), survivor) == around.end())
            around.push_back(survivor);
        std::vector<int>& kept = m_adjacent[static_cast<std::size_t>(survivor)];
        if (std::find(kept.begin(), kept.end(), k) == kept.end())
            kept.push_back(k);
    }
    m_adjacent[static_cast<std::size_t>(loser)].clear();
    m_absorbedBy[static_cast<std::size_t>(loser)] = survivor;
    m_regionSize[static_cast<std::size_t>(survivor)] += m_regionSize[static_cast<std::size_t>(loser)];
    --m_aliveCount;
}

// Walks from `leaf` along degree-2 nodes to the first junction; merges the chain into it
// when the chain is spurious (see the header). Returns whether it did.
bool NodeGraph::pruneBranchFrom(int leaf)
{
    std::vector<int> chain{leaf};
    int previous = leaf, current = m_adjacent[static_cast<std::size_t>(leaf)].front();
    double branchLength = length(leaf, current);
    std::size_t branchRegion = m_regionSize[static_cast<std::size_t>(leaf)];
    while (degree(current) == 2) {
        const std::vector<int>& around = m_adjacent[static_cast<std::size_t>(current)];
        const int next = around[0] == previous ? around[1] : around[0];
        chain.push_back(current);
        branchLength += length(current, next);
        branchRegion += m_regionSize[static_cast<std::size_t>(current)];
        previous = current;
        current = next;
    }
    if (degree(current) < 3)
        return false; // the graph is a path: its ends are the arms
    const auto junction = static_cast<std::size_t>(current);
    const bool inside = branchLength < m_radius[junction];
    const bool tiny =
        static_cast<double>(branchRegion) < kSpuriousRegionFraction * static_cast<double>(m_curveRegionSize[junction]);
    if (!inside && !tiny)
        return false; // the branch sticks out and carries surface: an arm
    for (int k : chain)
        merge(k, current);
    return true;
}

std::size_t NodeGraph::pruneSpuriousBranches()
{
    std::size_t pruned = 0;
    for (bool changed = true; changed;) {
        changed = false;
        for (int k = 0; k < static_cast<int>(m_adjacent.size()); ++k)
            if (m_absorbedBy[static_cast<std::size_t>(k)] < 0 && degree(k) == 1 && pruneBranchFrom(k)) {
                ++pruned;
                changed = true;
            }
    }
    return pruned;
}

// Two junctions whose clearance balls (radius: the distance to the nearest mesh vertex)
// overlap lie in one body: one branching point split in two by the simplification (a
// four-arm star's hub often becomes two degree-3 nodes). Merges the shortest such edge
// first, repeatedly; returns the merges.
std::size_t NodeGraph::mergeNearbyJunctions()
{
    std::size_t merged = 0;
    for (;;) {
        std::vector<std::tuple<double, int, int>> candidates;
        for (int a = 0; a < static_cast<int>(m_adjacent.size()); ++a)
            for (int b : m_adjacent[static_cast<std::size_t>(a)])
                if (a < b && degree(a) >= 3 && degree(b) >= 3)
                    if (const double d = length(a, b);
                        d < m_clearance[static_cast<std::size_t>(a)] + m_clearance[static_cast<std::size_t>(b)])
                        candidates.emplace_back(d, a, b);
        std::sort(candidates.begin(), candidates.end());
        bool done = false;
        for (const auto& [d, a, b] : candidates) {
            const int kept = survivor(a, b);
            const int lost = kept == a ? b : a;
            if (mergeStaysInside(lost, kept)) {
                merge(lost, kept);
                ++merged;
                done = true;
                break;
            }
        }
        if (!done)
            return merged;
    }
}

bool NodeGraph::eligible(int a, int b) const
{
    const int da = degree(a), db = degree(b);
    if ((da == 1 && db >= 3) || (db == 1 && da >= 3))
        return false;             // would remove an arm
    return !(da == 1 && db == 1); // a lone edge: both of its ends are arm ends
}

int NodeGraph::survivor(int a, int b) const
{
    // With the solid known, a node inside outranks one the refinement could not place
    // inside, so a joint never sits outside when its neighbour could have served.
    const auto key = [&](int k) {
        const bool inside = m_solid == nullptr || m_solid->contains(m_positions[static_cast<std::size_t>(k)]);
        return std::make_tuple(inside, degree(k) == 1, degree(k), m_regionSize[static_cast<std::size_t>(k)], -k);
    };
    return key(a) > key(b) ? a : b;
}

bool NodeGraph::collapseShortest()
{
    // Shortest first, ties by the lower pair; the first whose new edges stay inside.
    std::vector<std::tuple<double, int, int>> candidates;
    for (int a = 0; a < static_cast<int>(m_adjacent.size()); ++a)
        for (int b : m_adjacent[static_cast<std::size_t>(a)])
            if (a < b && eligible(a, b))
                candidates.emplace_back(length(a, b), a, b);
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [d, a, b] : candidates) {
        const int kept = survivor(a, b);
        const int lost = kept == a ? b : a;
        if (mergeStaysInside(lost, kept)) {
            merge(lost, kept);
            return true;
        }
    }
    return false;
}

NodeSelection NodeGraph::result() const
{
    NodeSelection selection;
    std::vector<int> jointIndex(m_adjacent.size(), -1);
    for (std::size_t k = 0; k < m_adjacent.size(); ++k)
        if (m_absorbedBy[k] < 0) {
            jointIndex[k] = static_cast<int>(selection.survivors.size());
            selection.survivors.push_back(static_cast<int>(k));
        }
    selection.jointOfNode.resize(m_adjacent.size());
    for (std::size_t k = 0; k < m_adjacent.size(); ++k)
        selection.jointOfNode[k] = jointIndex[static_cast<std::size_t>(find(static_cast<int>(k)))];
    for (int a : selection.survivors)
        for (int b : m_adjacent[static_cast<std::size_t>(a)])
            if (a < b)
                selection.edges.push_back(
                    {jointIndex[static_cast<std::size_t>(a)], jointIndex[static_cast<std::size_t>(b)]});
    std::sort(selection.edges.begin(), selection.edges.end());
    return selection;
}

} // namespace

NodeSelection selectSkeletonNodes(const CurveSkeleton& curve, std::span<const glm::dvec3> originalPositions,
                                  int targetNodes, const PointInMesh* solid)
{
    if (targetNodes < 1)
        throw std::invalid_argument("selectSkeletonNodes: the target must be at least 1 node, not " +
                                    std::to_string(targetNodes));
    if (curve.vertexNode.size() != originalPositions.size())
        throw std::invalid_argument("selectSkeletonNodes: vertexNode has " + std::to_string(curve.vertexNode.size()) +
                                    " entries for " + std::to_string(originalPositions.size()) + " vertices");
    NodeGraph graph(curve, originalPositions, solid);
    std::size_t pruned = 0;
    for (bool changed = true; changed;) { // merging junctions can leave new spurious branches
        const std::size_t branches = graph.pruneSpuriousBranches();
        pruned += branches;
        changed = graph.mergeNearbyJunctions() > 0;
    }
    while (graph.aliveCount() > static_cast<std::size_t>(targetNodes) && graph.collapseShortest()) {
    }
    NodeSelection selection = graph.result();
    selection.prunedBranches = pruned;
    return selection;
}

} // namespace trimlab
