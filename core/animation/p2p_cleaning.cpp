#include "core/animation/p2p_cleaning.h"

#include "core/animation/vertex_areas.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace trimlab {

namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

// Union-find whose root is always the smallest member, so results do not depend on the
// order of unions.
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t s)
{
    std::uint32_t root = s;
    while (parent[root] != root)
        root = parent[root];
    while (parent[s] != root) {
        const std::uint32_t next = parent[s];
        parent[s] = root;
        s = next;
    }
    return root;
}

void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b)
{
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a != b)
        parent[std::max(a, b)] = std::min(a, b);
}

// Pairs of different segments joined by at least one mesh edge, sorted, unique.
std::vector<std::pair<std::uint32_t, std::uint32_t>> segmentAdjacency(const VertexGraph& graph,
                                                                      const std::vector<std::uint32_t>& segment)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t v = 0; v < graph.vertexCount(); ++v) {
        for (const std::uint32_t n : graph.neighborsOf(v)) {
            if (v < n && segment[v] != segment[n])
                pairs.emplace_back(std::min(segment[v], segment[n]), std::max(segment[v], segment[n]));
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

// a ≤ b for areas: sums of the same vertex areas in different orders differ in the last
// bits, and a segment that fills its whole cluster must pass 3.1 at h = 1 every time.
bool atMost(double a, double b)
{
    return a <= b * (1.0 + 1e-12);
}

// The index i < k with levels i equal and i + 1 different for two neighbouring segments:
// the pose (0-based partition index) whose partition separates them first.
std::size_t separatingPose(const std::vector<std::uint32_t>& levelOf, std::size_t r, std::size_t poses, std::uint32_t a,
                           std::uint32_t b)
{
    std::size_t low = 0;      // levels equal here (level 0: both in one component)
    std::size_t high = poses; // levels differ here (different final segments)
    while (high - low > 1) {
        const std::size_t mid = (low + high) / 2;
        (levelOf[mid * r + a] == levelOf[mid * r + b] ? low : high) = mid;
    }
    return low;
}

} // namespace

// The union-find forest over the r segments and the per-pose scratch arrays.
struct P2pCleaner::CleaningState {
    std::vector<std::uint32_t> parent;
    std::vector<double> area;          // true area of every root
    std::vector<std::uint32_t> target; // S_B of a root during one pose, kNone otherwise
    std::vector<std::uint32_t> rank;   // position of every segment in the visiting order
    std::vector<std::uint32_t> touched;
};

P2pCleaner::P2pCleaner(const PoseJoin& join, std::span<const double> areas)
    : m_poses(join.partitionCount()), m_vertexSegment(join.overSegmentation().labels)
{
    const std::size_t vertexCount = join.graph().vertexCount();
    if (areas.size() != vertexCount)
        throw std::invalid_argument("P2pCleaner: " + std::to_string(areas.size()) + " areas for " +
                                    std::to_string(vertexCount) + " vertices");
    const std::size_t r = join.overSegmentation().count;
    m_segmentArea = labelAreas(m_vertexSegment, r, areas);
    // Every segment lies inside one segment of each prefix level and one cluster of each
    // pose, so its first vertex tells which.
    std::vector<std::uint32_t> firstVertex(r, kNone);
    for (std::size_t v = vertexCount; v-- > 0;)
        firstVertex[m_vertexSegment[v]] = std::uint32_t(v);
    m_levelOf.resize((m_poses + 1) * r);
    m_clusterOf.resize(m_poses * r);
    for (std::size_t i = 0; i <= m_poses; ++i) {
        const VertexLabeling& level = join.level(i);
        for (std::size_t s = 0; s < r; ++s)
            m_levelOf[i * r + s] = level.labels[firstVertex[s]];
        m_levelArea.push_back(labelAreas(std::span(m_levelOf).subspan(i * r, r), level.count, m_segmentArea));
    }
    for (std::size_t p = 0; p < m_poses; ++p) {
        const VertexLabeling& partition = join.partition(p);
        for (std::size_t s = 0; s < r; ++s)
            m_clusterOf[p * r + s] = partition.labels[firstVertex[s]];
        m_clusterArea.push_back(labelAreas(std::span(m_clusterOf).subspan(p * r, r), partition.count, m_segmentArea));
    }
    std::vector<std::pair<std::size_t, std::pair<std::uint32_t, std::uint32_t>>> byPose;
    for (const auto& [a, b] : segmentAdjacency(join.graph(), m_vertexSegment))
        byPose.push_back({separatingPose(m_levelOf, r, m_poses, a, b), {a, b}});
    std::sort(byPose.begin(), byPose.end());
    m_pairStart.assign(m_poses + 1, 0);
    for (const auto& [pose, pair] : byPose) {
        ++m_pairStart[pose + 1];
        m_pairs.push_back(pair);
    }
    for (std::size_t p = 0; p < m_poses; ++p)
        m_pairStart[p + 1] += m_pairStart[p];
}

VertexLabeling P2pCleaner::clean(double h) const
{
    std::vector<std::uint32_t> order(m_segmentArea.size());
    std::iota(order.begin(), order.end(), 0u);
    return clean(h, order);
}

VertexLabeling P2pCleaner::clean(double h, std::span<const std::uint32_t> order) const
{
    const std::size_t r = m_segmentArea.size();
    CleaningState state;
    state.rank.assign(r, kNone);
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (order[i] >= r || state.rank[order[i]] != kNone)
            throw std::invalid_argument("P2pCleaner::clean: the order is not a permutation of the segments");
        state.rank[order[i]] = std::uint32_t(i);
    }
    if (order.size() != r)
        throw std::invalid_argument("P2pCleaner::clean: the order is not a permutation of the segments");
    state.parent.resize(r);
    std::iota(state.parent.begin(), state.parent.end(), 0u);
    state.area = m_segmentArea;
    state.target.assign(r, kNone);
    if (h > 0.0) {
        for (std::size_t pose = m_poses; pose-- > 0;)
            cleanPose(pose, h, state);
    }
    std::vector<std::uint32_t> labels(m_vertexSegment.size());
    for (std::size_t v = 0; v < labels.size(); ++v)
        labels[v] = findRoot(state.parent, m_vertexSegment[v]);
    return canonicalLabeling(labels);
}

// R_i(h) for pose i = pose + 1 (thesis numbering): levels `pose` and `pose + 1` are
// segment(·, i − 1) and segment(·, i); partition `pose` is C_i.
void P2pCleaner::cleanPose(std::size_t pose, double h, CleaningState& state) const
{
    // Decisions on the segmentation as this pose begins: S_B is the largest neighbour of
    // larger area among those this pose separates (conditions 3.3 and 3.4).
    state.touched.clear();
    auto consider = [&](std::uint32_t a, std::uint32_t b) {
        if (!(state.area[b] > state.area[a]))
            return;
        std::uint32_t& t = state.target[a];
        if (t == kNone)
            state.touched.push_back(a);
        if (t == kNone || state.area[b] > state.area[t] || (state.area[b] == state.area[t] && b < t))
            t = b;
    };
    for (std::size_t i = m_pairStart[pose]; i < m_pairStart[pose + 1]; ++i) {
        const std::uint32_t a = findRoot(state.parent, m_pairs[i].first);
        const std::uint32_t b = findRoot(state.parent, m_pairs[i].second);
        if (a != b) {
            consider(a, b);
            consider(b, a);
        }
    }
    // Conditions 3.1 and 3.2 (S_A is small), visited in the requested order; then all
    // absorptions of this pose together, each root's area becoming the true sum.
    std::sort(state.touched.begin(), state.touched.end(),
              [&](std::uint32_t x, std::uint32_t y) { return state.rank[x] < state.rank[y]; });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> absorptions;
    for (const std::uint32_t a : state.touched) {
        const double cluster = m_clusterArea[pose][clusterOf(pose, a)];
        const double previous = m_levelArea[pose][levelOf(pose, a)];
        if (atMost(state.area[a], h * cluster) && atMost(state.area[a], h * previous))
            absorptions.emplace_back(a, state.target[a]);
        state.target[a] = kNone;
    }
    for (const auto& [a, b] : absorptions) {
        const std::uint32_t ra = findRoot(state.parent, a);
        const std::uint32_t rb = findRoot(state.parent, b);
        if (ra == rb)
            continue;
        const double merged = state.area[ra] + state.area[rb];
        unite(state.parent, ra, rb);
        state.area[std::min(ra, rb)] = merged;
    }
}

} // namespace trimlab
