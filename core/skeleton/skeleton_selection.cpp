#include "core/skeleton/skeleton_selection.h"

#include "core/skeleton/body_root.h"
#include "core/skeleton/rig_measures.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
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

// A limb is a joint of its own only when it is at least this many joint spacings
// (the alive curve's length over the target count) long; shorter ones (fingers, toes
// when the budget is a few dozen joints) merge into their junction, so the joints go
// where the body bends rather than to its smallest branches.
constexpr double kMinimumLimbSpacings = 1.0;

// A chord that strays from its curve by more than this fraction of its length is a
// bend, split at the node farthest from it (an elbow held bent).
constexpr double kBendFraction = 0.1;

// A bone turns back on its parent beyond rig_measures.h's kTurnBackDegrees: the cosine.
const double kTurnBackCosine = std::cos(kTurnBackDegrees * std::numbers::pi / 180.0);

// A path of the alive graph between two branch nodes (degree other than 2) through
// degree-2 nodes; a loop starts and ends at the same node.
struct Chain {
    std::vector<int> nodes;  // ends included
    std::vector<double> arc; // arc length from nodes.front() to each node
    [[nodiscard]] double length() const { return arc.back(); }
};

// The part of a chain between two of its placed joints (indices into Chain::nodes).
struct ChainSegment {
    int chain = 0;
    int first = 0;
    int last = 0;
};

// The curve skeleton as a mutable graph whose collapses merge regions.
class NodeGraph {
public:
    NodeGraph(const CurveSkeleton& curve, std::span<const glm::dvec3> originalPositions, const PointInMesh* solid);

    [[nodiscard]] int degree(int k) const { return static_cast<int>(m_adjacent[static_cast<std::size_t>(k)].size()); }
    [[nodiscard]] std::size_t aliveCount() const { return m_aliveCount; }
    std::size_t pruneSpuriousBranches();
    std::size_t mergeNearbyJunctions();
    std::size_t pruneBelowResolution(int targetNodes);
    void placeJoints(int targetNodes);
    [[nodiscard]] int bodyRootNode() const;
    std::size_t straightenTurnBacks(int root);
    [[nodiscard]] bool turnsBack(int grand, int head, int tail) const;
    [[nodiscard]] bool canHold(int holder, int tail, const std::vector<int>& parent);
    [[nodiscard]] NodeSelection result() const;

private:
    [[nodiscard]] double length(int a, int b) const
    {
        return glm::length(m_positions[static_cast<std::size_t>(a)] - m_positions[static_cast<std::size_t>(b)]);
    }
    [[nodiscard]] int survivor(int a, int b) const;
    [[nodiscard]] std::vector<int> parentsFrom(int root) const;
    [[nodiscard]] std::vector<Chain> chains() const;
    [[nodiscard]] std::vector<Chain> limbs() const;
    [[nodiscard]] double aliveLength() const;
    [[nodiscard]] std::size_t branchNodeCount() const;
    [[nodiscard]] bool isBranchNode(int k) const { return degree(k) != 2; }
    [[nodiscard]] int splitPoint(const Chain& chain, const ChainSegment& segment, int previousPlaced, int nextPlaced);
    [[nodiscard]] bool mustSplit(const Chain& chain, const ChainSegment& segment,
                                 const std::map<std::pair<int, int>, int>& pairCount);

    void mergeUnplaced(const Chain& chain, const std::vector<char>& placed);
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

double NodeGraph::aliveLength() const
{
    double total = 0.0;
    for (int a = 0; a < static_cast<int>(m_adjacent.size()); ++a)
        for (int b : m_adjacent[static_cast<std::size_t>(a)])
            if (a < b)
                total += length(a, b);
    return total;
}

std::size_t NodeGraph::branchNodeCount() const
{
    std::size_t count = 0;
    for (int k = 0; k < static_cast<int>(m_adjacent.size()); ++k)
        if (m_absorbedBy[static_cast<std::size_t>(k)] < 0 && isBranchNode(k))
            ++count;
    return count;
}

// Every chain of the alive graph, each once. A component without a branch node (the
// loop of a torus) starts at its lowest node.
std::vector<Chain> NodeGraph::chains() const
{
    const auto n = static_cast<int>(m_adjacent.size());
    std::vector<char> isStart(m_adjacent.size(), 0), reached(m_adjacent.size(), 0);
    const auto reach = [&](int from) {
        std::vector<int> stack{from};
        reached[static_cast<std::size_t>(from)] = 1;
        while (!stack.empty()) {
            const int k = stack.back();
            stack.pop_back();
            for (int next : m_adjacent[static_cast<std::size_t>(k)])
                if (!reached[static_cast<std::size_t>(next)]) {
                    reached[static_cast<std::size_t>(next)] = 1;
                    stack.push_back(next);
                }
        }
    };
    for (int k = 0; k < n; ++k)
        if (m_absorbedBy[static_cast<std::size_t>(k)] < 0 && isBranchNode(k)) {
            isStart[static_cast<std::size_t>(k)] = 1;
            if (!reached[static_cast<std::size_t>(k)])
                reach(k);
        }
    for (int k = 0; k < n; ++k)
        if (m_absorbedBy[static_cast<std::size_t>(k)] < 0 && !reached[static_cast<std::size_t>(k)]) {
            isStart[static_cast<std::size_t>(k)] = 1;
            reach(k);
        }

    std::vector<Chain> result;
    std::set<std::pair<int, int>> walked;
    const auto step = [&](int a, int b) { return walked.insert({std::min(a, b), std::max(a, b)}).second; };
    for (int start = 0; start < n; ++start) {
        if (!isStart[static_cast<std::size_t>(start)])
            continue;
        for (int next : m_adjacent[static_cast<std::size_t>(start)]) {
            if (!step(start, next))
                continue;
            Chain chain{{start}, {0.0}};
            for (int previous = start, current = next;;) {
                chain.nodes.push_back(current);
                chain.arc.push_back(chain.arc.back() + length(previous, current));
                if (isStart[static_cast<std::size_t>(current)])
                    break;
                const std::vector<int>& around = m_adjacent[static_cast<std::size_t>(current)];
                const int following = around[0] == previous ? around[1] : around[0];
                step(current, following);
                previous = current;
                current = following;
            }
            result.push_back(std::move(chain));
        }
    }
    return result;
}

// The chains from a leaf to a junction, leaf first.
std::vector<Chain> NodeGraph::limbs() const
{
    std::vector<Chain> result;
    for (Chain& chain : chains()) {
        const int front = degree(chain.nodes.front()), back = degree(chain.nodes.back());
        if (front == 1 && back >= 3) {
            result.push_back(std::move(chain));
        } else if (back == 1 && front >= 3) {
            std::reverse(chain.nodes.begin(), chain.nodes.end());
            const double total = chain.length();
            std::reverse(chain.arc.begin(), chain.arc.end());
            for (double& a : chain.arc)
                a = total - a;
            result.push_back(std::move(chain));
        }
    }
    return result;
}

// Merges the shortest limb into its junction while it is shorter than the joint spacing
// the target allows, or while there are more branch nodes than the target.
std::size_t NodeGraph::pruneBelowResolution(int targetNodes)
{
    std::size_t pruned = 0;
    for (;;) {
        const std::vector<Chain> candidates = limbs();
        if (candidates.empty())
            return pruned;
        const auto shortest =
            std::min_element(candidates.begin(), candidates.end(), [](const Chain& a, const Chain& b) {
                return std::make_pair(a.length(), a.nodes.front()) < std::make_pair(b.length(), b.nodes.front());
            });
        const double spacing = aliveLength() / static_cast<double>(targetNodes);
        const bool belowResolution = shortest->length() < kMinimumLimbSpacings * spacing;
        const bool overBudget = branchNodeCount() > static_cast<std::size_t>(targetNodes);
        if (!belowResolution && !overBudget)
            return pruned;
        // With it go its siblings below the spacing too, so that a hand whose fingers all
        // go ends the arm rather than leaving its last finger as the arm's tip.
        const int junction = shortest->nodes.back();
        for (const Chain& limb : candidates)
            if (limb.nodes.back() == junction &&
                (&limb == &*shortest || limb.length() < kMinimumLimbSpacings * spacing)) {
                for (std::size_t i = 0; i + 1 < limb.nodes.size(); ++i)
                    merge(limb.nodes[i], junction);
                ++pruned;
            }
    }
}

// Whether a segment has to be split whatever the target: its chord leaves the solid,
// it closes a loop on one joint, or another segment joins the same two joints (the
// joints' graph would have a double edge).
bool NodeGraph::mustSplit(const Chain& chain, const ChainSegment& segment,
                          const std::map<std::pair<int, int>, int>& pairCount)
{
    const int a = chain.nodes[static_cast<std::size_t>(segment.first)];
    const int b = chain.nodes[static_cast<std::size_t>(segment.last)];
    if (a == b || pairCount.at({std::min(a, b), std::max(a, b)}) > 1)
        return true;
    return m_solid != nullptr && !segmentInside(a, b);
}

// Where a segment gains its joint: at the node farthest from its chord when the chain
// bends there (or must be split), otherwise at the narrowest node of its middle half
// (a knee or an elbow held straight narrows the limb), by the mean distance to the
// node's own vertices. Nodes where the two new bones would turn back on each other
// (a zig-zag of the curve through a hub) are passed over while any other serves.
int NodeGraph::splitPoint(const Chain& chain, const ChainSegment& segment, int previousPlaced, int nextPlaced)
{
    const auto nodeAt = [&](int i) { return static_cast<std::size_t>(chain.nodes[static_cast<std::size_t>(i)]); };
    const auto arcAt = [&](int i) { return chain.arc[static_cast<std::size_t>(i)]; };
    const int first = chain.nodes[static_cast<std::size_t>(segment.first)];
    const int last = chain.nodes[static_cast<std::size_t>(segment.last)];
    const glm::dvec3 a = m_positions[static_cast<std::size_t>(first)];
    const glm::dvec3 b = m_positions[static_cast<std::size_t>(last)];
    const double chordLength = glm::length(b - a);
    const auto cosine = [](const glm::dvec3& in, const glm::dvec3& out) {
        const double lengths = glm::length(in) * glm::length(out);
        return lengths == 0.0 ? 1.0 : glm::dot(in, out) / lengths;
    };
    // The joints placed before and after the segment on its chain, when there are.
    const std::optional<glm::dvec3> before =
        segment.first > 0 ? std::optional(m_positions[nodeAt(previousPlaced)]) : std::nullopt;
    const std::optional<glm::dvec3> after = segment.last + 1 < static_cast<int>(chain.nodes.size())
                                                ? std::optional(m_positions[nodeAt(nextPlaced)])
                                                : std::nullopt;
    const auto turn = [&](int i) { // the sharpest turn the new joint makes along the chain; 1 when straight
        if (first == last)
            return 1.0;
        const glm::dvec3 p = m_positions[nodeAt(i)];
        double sharpest = cosine(p - a, b - p);
        if (before)
            sharpest = std::min(sharpest, cosine(a - *before, p - a));
        if (after)
            sharpest = std::min(sharpest, cosine(b - p, *after - b));
        return sharpest;
    };
    const auto offChord = [&](int i) {
        const glm::dvec3 p = m_positions[nodeAt(i)];
        const double t =
            chordLength > 0.0 ? std::clamp(glm::dot(p - a, b - a) / (chordLength * chordLength), 0.0, 1.0) : 0.0;
        return glm::length(p - (a + t * (b - a)));
    };

    int gentlest = segment.first + 1, farthest = -1, middle = -1, narrowest = -1;
    double bend = 0.0;
    const double span = arcAt(segment.last) - arcAt(segment.first);
    const auto along = [&](int i) { return span > 0.0 ? (arcAt(i) - arcAt(segment.first)) / span : 0.5; };
    for (int i = segment.first + 1; i < segment.last; ++i) {
        bend = std::max(bend, offChord(i));
        if (turn(i) > turn(gentlest))
            gentlest = i;
        if (turn(i) < kTurnBackCosine)
            continue;
        if (farthest < 0 || offChord(i) > offChord(farthest))
            farthest = i;
        if (middle < 0 || std::abs(along(i) - 0.5) < std::abs(along(middle) - 0.5))
            middle = i;
        const std::size_t node = nodeAt(i);
        if (along(i) >= 0.25 && along(i) <= 0.75 && m_curveRegionSize[node] > 0 &&
            (narrowest < 0 || m_radius[node] < m_radius[nodeAt(narrowest)]))
            narrowest = i;
    }
    if (farthest < 0)
        return gentlest;
    if (first == last || bend > kBendFraction * chordLength || (m_solid != nullptr && !segmentInside(first, last)))
        return farthest;
    return narrowest >= 0 ? narrowest : middle;
}

// Each chain node that is not a joint joins the nearer joint along the chain.
void NodeGraph::mergeUnplaced(const Chain& chain, const std::vector<char>& placed)
{
    int previous = 0;
    for (std::size_t i = 1; i + 1 < chain.nodes.size(); ++i) {
        if (placed[i]) {
            previous = static_cast<int>(i);
            continue;
        }
        std::size_t next = i + 1;
        while (!placed[next])
            ++next;
        const double back = chain.arc[i] - chain.arc[static_cast<std::size_t>(previous)];
        const double ahead = chain.arc[next] - chain.arc[i];
        merge(chain.nodes[i], chain.nodes[back <= ahead ? static_cast<std::size_t>(previous) : next]);
    }
}

// The parent of each alive node in a breadth-first tree from `root` (−1 for the root
// and for nodes it does not reach).
std::vector<int> NodeGraph::parentsFrom(int root) const
{
    std::vector<int> parent(m_adjacent.size(), -1);
    std::vector<char> seen(m_adjacent.size(), 0);
    std::deque<int> queue{root};
    seen[static_cast<std::size_t>(root)] = 1;
    while (!queue.empty()) {
        const int k = queue.front();
        queue.pop_front();
        std::vector<int> around = m_adjacent[static_cast<std::size_t>(k)];
        std::sort(around.begin(), around.end());
        for (int next : around)
            if (!seen[static_cast<std::size_t>(next)]) {
                seen[static_cast<std::size_t>(next)] = 1;
                parent[static_cast<std::size_t>(next)] = k;
                queue.push_back(next);
            }
    }
    return parent;
}

// Whether the bone from `head` to `tail` turns back on the bone from `grand` to `head`.
bool NodeGraph::turnsBack(int grand, int head, int tail) const
{
    const glm::dvec3 g = m_positions[static_cast<std::size_t>(grand)];
    const glm::dvec3 h = m_positions[static_cast<std::size_t>(head)];
    const glm::dvec3 t = m_positions[static_cast<std::size_t>(tail)];
    const double lengths = glm::length(h - g) * glm::length(t - h);
    return lengths > 0.0 && glm::dot(h - g, t - h) < kTurnBackCosine * lengths;
}

// Whether `holder` can take `tail` as a child: not joined already, the bone stays
// inside and does not turn back on the bone into the holder.
bool NodeGraph::canHold(int holder, int tail, const std::vector<int>& parent)
{
    const std::vector<int>& around = m_adjacent[static_cast<std::size_t>(holder)];
    if (std::find(around.begin(), around.end(), tail) != around.end())
        return false;
    const int above = parent[static_cast<std::size_t>(holder)];
    if (above >= 0 && turnsBack(above, holder, tail))
        return false;
    return m_solid == nullptr || segmentInside(holder, tail);
}

// A bone that turns back on its parent bone by more than 120° is straightened, when the
// new bone stays inside the solid: at a joint of two bones (a zig-zag of the curve) the
// joint goes and its bones become one; at a junction (an arm whose curve leaves the
// neck hub down through the chest, a toe beyond the heel) the bone is hung from the
// nearest joint up the tree that can hold it without turning back. The first such bone
// in node order each time, until none is left that can be straightened.
std::size_t NodeGraph::straightenTurnBacks(int root)
{
    std::size_t moved = 0;
    for (std::size_t pass = 0; pass < m_adjacent.size(); ++pass) {
        const std::vector<int> parent = parentsFrom(root);
        bool changed = false;
        for (int tail = 0; tail < static_cast<int>(m_adjacent.size()) && !changed; ++tail) {
            const int head = parent[static_cast<std::size_t>(tail)];
            const int grand = head < 0 ? -1 : parent[static_cast<std::size_t>(head)];
            if (grand < 0)
                continue;
            if (!turnsBack(grand, head, tail))
                continue;
            if (degree(head) == 2) { // a zig-zag: the joint goes, its bones become one
                if (m_solid != nullptr && !segmentInside(grand, tail))
                    continue;
                merge(head, grand);
                changed = true;
                ++moved;
                continue;
            }
            // The nearest joint up the chain that can hold the bone without a turn-back.
            int holder = grand;
            while (holder >= 0 && !canHold(holder, tail, parent))
                holder = parent[static_cast<std::size_t>(holder)];
            if (holder < 0)
                continue;
            std::vector<int>& aroundHead = m_adjacent[static_cast<std::size_t>(head)];
            std::vector<int>& aroundTail = m_adjacent[static_cast<std::size_t>(tail)];
            aroundHead.erase(std::remove(aroundHead.begin(), aroundHead.end(), tail), aroundHead.end());
            aroundTail.erase(std::remove(aroundTail.begin(), aroundTail.end(), head), aroundTail.end());
            aroundTail.push_back(holder);
            m_adjacent[static_cast<std::size_t>(holder)].push_back(tail);
            changed = true;
            ++moved;
        }
        if (!changed)
            break;
    }
    return moved;
}

// The body's root (body_root.h) among the alive nodes; a node index.
int NodeGraph::bodyRootNode() const
{
    std::vector<int> compact(m_adjacent.size(), -1), alive;
    for (std::size_t k = 0; k < m_adjacent.size(); ++k)
        if (m_absorbedBy[k] < 0) {
            compact[k] = static_cast<int>(alive.size());
            alive.push_back(static_cast<int>(k));
        }
    std::vector<std::vector<int>> adjacent(alive.size());
    std::vector<std::size_t> mass(alive.size());
    for (std::size_t i = 0; i < alive.size(); ++i) {
        const auto k = static_cast<std::size_t>(alive[i]);
        mass[i] = m_regionSize[k];
        for (int next : m_adjacent[k])
            adjacent[i].push_back(compact[static_cast<std::size_t>(next)]);
    }
    return alive.empty() ? -1 : alive[static_cast<std::size_t>(bodyRoot(adjacent, mass))];
}

// The branch nodes stay; the chains between them gain joints, first where a chord must
// be split, then on the longest segment, until the target is reached.
void NodeGraph::placeJoints(int targetNodes)
{
    const std::vector<Chain> all = chains();
    std::vector<std::vector<char>> placed;
    std::vector<ChainSegment> segments;
    std::map<std::pair<int, int>, int> pairCount;
    const auto pairOf = [&](const ChainSegment& s) {
        const int a = all[static_cast<std::size_t>(s.chain)].nodes[static_cast<std::size_t>(s.first)];
        const int b = all[static_cast<std::size_t>(s.chain)].nodes[static_cast<std::size_t>(s.last)];
        return std::make_pair(std::min(a, b), std::max(a, b));
    };
    std::size_t interior = 0;
    for (std::size_t c = 0; c < all.size(); ++c) {
        const std::size_t size = all[c].nodes.size();
        placed.emplace_back(size, 0);
        placed.back().front() = placed.back().back() = 1;
        interior += size - 2;
        segments.push_back({static_cast<int>(c), 0, static_cast<int>(size) - 1});
        ++pairCount[pairOf(segments.back())];
    }
    std::size_t joints = m_aliveCount - interior;
    for (;;) {
        int pick = -1;
        for (std::size_t s = 0; s < segments.size() && pick < 0; ++s)
            if (segments[s].last - segments[s].first >= 2 &&
                mustSplit(all[static_cast<std::size_t>(segments[s].chain)], segments[s], pairCount))
                pick = static_cast<int>(s);
        if (pick < 0 && joints < static_cast<std::size_t>(targetNodes)) {
            double longest = 0.0;
            for (std::size_t s = 0; s < segments.size(); ++s) {
                const ChainSegment& segment = segments[s];
                const Chain& chain = all[static_cast<std::size_t>(segment.chain)];
                const double arc = chain.arc[static_cast<std::size_t>(segment.last)] -
                                   chain.arc[static_cast<std::size_t>(segment.first)];
                if (segment.last - segment.first >= 2 && arc > longest) {
                    longest = arc;
                    pick = static_cast<int>(s);
                }
            }
        }
        if (pick < 0)
            break;
        const ChainSegment segment = segments[static_cast<std::size_t>(pick)];
        const std::vector<char>& onChain = placed[static_cast<std::size_t>(segment.chain)];
        int previousPlaced = segment.first - 1, nextPlaced = segment.last + 1;
        while (previousPlaced > 0 && !onChain[static_cast<std::size_t>(previousPlaced)])
            --previousPlaced;
        while (nextPlaced + 1 < static_cast<int>(onChain.size()) && !onChain[static_cast<std::size_t>(nextPlaced)])
            ++nextPlaced;
        const int split = splitPoint(all[static_cast<std::size_t>(segment.chain)], segment, previousPlaced, nextPlaced);
        --pairCount[pairOf(segment)];
        segments[static_cast<std::size_t>(pick)] = {segment.chain, segment.first, split};
        segments.push_back({segment.chain, split, segment.last});
        ++pairCount[pairOf(segments[static_cast<std::size_t>(pick)])];
        ++pairCount[pairOf(segments.back())];
        placed[static_cast<std::size_t>(segment.chain)][static_cast<std::size_t>(split)] = 1;
        ++joints;
    }
    for (std::size_t c = 0; c < all.size(); ++c)
        mergeUnplaced(all[c], placed[c]);
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
    pruned += graph.pruneBelowResolution(targetNodes);
    const int rootNode = graph.bodyRootNode();
    graph.placeJoints(targetNodes);
    if (rootNode >= 0)
        graph.straightenTurnBacks(rootNode);
    NodeSelection selection = graph.result();
    if (rootNode >= 0)
        selection.root = selection.jointOfNode[static_cast<std::size_t>(rootNode)];
    selection.prunedBranches = pruned;
    return selection;
}

} // namespace trimlab
