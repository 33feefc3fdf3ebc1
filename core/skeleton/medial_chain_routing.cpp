#include "core/skeleton/medial_chain_routing.h"

#include "core/skeleton/mesh_adjacency.h"
#include "core/util/parallel_for.h"
#include "core/util/point_kd_tree.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace trimlab {

namespace {

// Smoothing passes over a routed path: the grid's cells put a step in its direction every
// half spacing; a few passes of a [1 2 1] filter take that out without pulling a bent
// limb's path off its axis.
constexpr int kSmoothingPasses = 4;
// Medial points an end of a chain tries to see (the nearest first) and keeps as starts.
constexpr std::size_t kEndCandidates = 16;
constexpr std::size_t kEndAttachments = 4;
// How far around an end its medial points are looked for, in cells.
constexpr int kEndSearchCells = 6;

// Steps join a medial point to its nearest few within this many cells: the chord midpoints
// sample the medial axis unevenly, and only neighbouring cells left it in hundreds of
// pieces (a cow's mesh in almost a thousand). 3 cells give the same curves and cost a
// third more time.
constexpr int kStepCells = 2;
constexpr std::size_t kStepsPerPoint = 16;

// After the routing, the vertices a chain's nodes absorbed may lie this much farther from
// the whole curve than before (the largest distance over those vertices), or the chain
// stays as it was.
constexpr double kCoverageTolerance = 1.05;

// The guard's distances are to points this fraction of the spacing apart along the curve:
// within 0.0013 of the diagonal of the exact ones.
constexpr double kCoverageSampling = 0.25;

using Cell = std::array<std::int64_t, 3>;

std::uint64_t cellKey(const Cell& c)
{
    // 21 bits per axis: a grid of two million cells a side, far more than a skeleton's.
    constexpr std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return (std::uint64_t(c[0]) & mask) | ((std::uint64_t(c[1]) & mask) << 21) | ((std::uint64_t(c[2]) & mask) << 42);
}

// The medial points, one per cell, and the steps between them.
struct MedialGraph {
    glm::dvec3 origin{0.0};
    double cell = 1.0;
    std::vector<glm::dvec3> points;
    std::vector<double> radii;
    std::unordered_map<std::uint64_t, std::uint32_t> pointOfCell;
    VertexAdjacency steps; // per point: neighbour, cost of the step

    [[nodiscard]] Cell cellOf(const glm::dvec3& p) const
    {
        const glm::dvec3 c = glm::floor((p - origin) / cell);
        return {std::int64_t(c.x), std::int64_t(c.y), std::int64_t(c.z)};
    }
    [[nodiscard]] std::optional<std::uint32_t> pointIn(const Cell& c) const
    {
        const auto found = pointOfCell.find(cellKey(c));
        if (found == pointOfCell.end())
            return std::nullopt;
        return found->second;
    }
};

double stepCost(double length, double radiusA, double radiusB)
{
    const double mean = 0.5 * (radiusA + radiusB);
    return length / std::max(mean * mean, 1e-300);
}

MedialGraph medialGraph(const TriangleMesh& mesh, const std::vector<std::optional<glm::dvec3>>& midpoints, double cell)
{
    MedialGraph graph;
    graph.cell = cell;
    const Bounds bounds = computeBounds(mesh);
    graph.origin = glm::dvec3(bounds.min) - glm::dvec3(cell);

    // One point per cell: the midpoint of the longest chord through it (a chord across a
    // limb or a slab has its midpoint in the middle whatever its tilt; the longest is the
    // least likely to end on a nearby bump). Its radius is then the distance to the
    // nearest vertex — a query for a point deep inside visits many of a kd-tree's cells,
    // so it is asked once per cell, not once per vertex (which takes most of a second on a
    // mesh of 58k vertices).
    std::vector<double> halfChords;
    for (std::size_t v = 0; v < midpoints.size(); ++v) {
        if (!midpoints[v])
            continue;
        const double halfChord = glm::length(*midpoints[v] - glm::dvec3(mesh.positions[v]));
        if (!(halfChord > 0.0) || !std::isfinite(halfChord))
            continue;
        const auto [slot, added] =
            graph.pointOfCell.try_emplace(cellKey(graph.cellOf(*midpoints[v])), std::uint32_t(graph.points.size()));
        if (added) {
            graph.points.push_back(*midpoints[v]);
            halfChords.push_back(halfChord);
        } else if (halfChord > halfChords[slot->second]) {
            graph.points[slot->second] = *midpoints[v];
            halfChords[slot->second] = halfChord;
        }
    }
    std::vector<glm::dvec3> vertices(mesh.positions.begin(), mesh.positions.end());
    const PointKdTree tree(std::move(vertices));
    graph.radii.resize(graph.points.size());
    parallelFor(graph.points.size(), 0, [&](std::size_t i) {
        // The chord's own vertex is half a chord away: the search need not look farther.
        const double bound = halfChords[i] * halfChords[i];
        graph.radii[i] = std::sqrt(std::min(
            bound, tree.nearest(graph.points[i], std::numeric_limits<std::size_t>::max(), bound).distanceSquared));
    });

    graph.steps.resize(graph.points.size());
    parallelFor(graph.points.size(), 0, [&](std::size_t i) {
        const Cell c = graph.cellOf(graph.points[i]);
        std::vector<std::pair<double, std::uint32_t>> near;
        for (std::int64_t dx = -kStepCells; dx <= kStepCells; ++dx)
            for (std::int64_t dy = -kStepCells; dy <= kStepCells; ++dy)
                for (std::int64_t dz = -kStepCells; dz <= kStepCells; ++dz) {
                    const std::optional<std::uint32_t> j = graph.pointIn({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (!j || *j == i)
                        continue;
                    const double length = glm::length(graph.points[*j] - graph.points[i]);
                    // One point inside the other's ball, which holds no vertex: the segment
                    // lies in it, inside up to a triangle's bulge (the routed chain's edges
                    // are checked against the surface).
                    if (length < std::max(graph.radii[i], graph.radii[*j]))
                        near.emplace_back(length, *j);
                }
        const std::size_t kept = std::min(kStepsPerPoint, near.size());
        std::partial_sort(near.begin(), near.begin() + std::ptrdiff_t(kept), near.end());
        for (std::size_t k = 0; k < kept; ++k)
            graph.steps[i].emplace_back(near[k].second,
                                        stepCost(near[k].first, graph.radii[i], graph.radii[near[k].second]));
    });
    return graph;
}

// The medial points near `p` that it sees inside, nearest first, with the cost of the step.
std::vector<PathEnd> attachments(const glm::dvec3& p, const MedialGraph& graph, const PointInMesh& inside)
{
    std::vector<std::pair<double, std::uint32_t>> near;
    const Cell c = graph.cellOf(p);
    for (std::int64_t dx = -kEndSearchCells; dx <= kEndSearchCells; ++dx)
        for (std::int64_t dy = -kEndSearchCells; dy <= kEndSearchCells; ++dy)
            for (std::int64_t dz = -kEndSearchCells; dz <= kEndSearchCells; ++dz)
                if (const std::optional<std::uint32_t> j = graph.pointIn({c[0] + dx, c[1] + dy, c[2] + dz}))
                    near.emplace_back(glm::length(graph.points[*j] - p), *j);
    const std::size_t tried = std::min(kEndCandidates, near.size());
    std::partial_sort(near.begin(), near.begin() + std::ptrdiff_t(tried), near.end());
    std::vector<PathEnd> result;
    for (std::size_t k = 0; k < tried && result.size() < kEndAttachments; ++k)
        if (inside.segmentInside(p, graph.points[near[k].second])) {
            const double r = graph.radii[near[k].second];
            result.push_back({near[k].second, stepCost(near[k].first, r, r)});
        }
    return result;
}

void smooth(std::vector<glm::dvec3>& polyline)
{
    for (int pass = 0; pass < kSmoothingPasses; ++pass) {
        std::vector<glm::dvec3> next = polyline;
        for (std::size_t i = 1; i + 1 < polyline.size(); ++i)
            next[i] = 0.25 * polyline[i - 1] + 0.5 * polyline[i] + 0.25 * polyline[i + 1];
        polyline = std::move(next);
    }
}

// `count` points spread evenly by arc length strictly between the polyline's ends.
std::vector<glm::dvec3> spreadAlong(const std::vector<glm::dvec3>& polyline, std::size_t count)
{
    std::vector<double> at(polyline.size(), 0.0);
    for (std::size_t i = 1; i < polyline.size(); ++i)
        at[i] = at[i - 1] + glm::length(polyline[i] - polyline[i - 1]);
    std::vector<glm::dvec3> points;
    std::size_t segment = 1;
    for (std::size_t k = 1; k <= count; ++k) {
        const double s = at.back() * double(k) / double(count + 1);
        while (segment + 1 < polyline.size() && at[segment] < s)
            ++segment;
        const double span = at[segment] - at[segment - 1];
        const double t = span > 0.0 ? std::clamp((s - at[segment - 1]) / span, 0.0, 1.0) : 0.0;
        points.push_back(polyline[segment - 1] + t * (polyline[segment] - polyline[segment - 1]));
    }
    return points;
}

// Per position, the distance to the nearest of points sampled along the curve's edges no
// farther apart than `step` — within step/2 of the distance to the curve. The guard below
// compares coverage before and after the routing for every vertex; exactly, over every
// edge, that costs seconds on a mesh of a few hundred thousand vertices.
std::vector<double> distancesToCurveSamples(const std::vector<glm::vec3>& positions, const CurveSkeleton& curve,
                                            double step)
{
    std::vector<glm::dvec3> samples(curve.nodes.begin(), curve.nodes.end());
    for (const auto& e : curve.edges) {
        const glm::dvec3 a = curve.nodes[std::size_t(e[0])], b = curve.nodes[std::size_t(e[1])];
        const int pieces = std::max(1, int(std::ceil(glm::length(b - a) / step)));
        for (int i = 1; i < pieces; ++i)
            samples.push_back(a + (b - a) * (double(i) / pieces));
    }
    const PointKdTree tree(std::move(samples));
    std::vector<double> distance(positions.size(), std::numeric_limits<double>::infinity());
    parallelFor(positions.size(), 0, [&](std::size_t v) {
        distance[v] = std::sqrt(tree.nearest(glm::dvec3(positions[v])).distanceSquared);
    });
    return distance;
}

std::vector<std::vector<int>> neighbours(const CurveSkeleton& curve)
{
    std::vector<std::vector<int>> result(curve.nodes.size());
    for (const auto& e : curve.edges) {
        result[std::size_t(e[0])].push_back(e[1]);
        result[std::size_t(e[1])].push_back(e[0]);
    }
    return result;
}

// The chains between nodes of degree other than 2, each once, ends included.
std::vector<std::vector<int>> chains(const std::vector<std::vector<int>>& adjacent)
{
    std::vector<std::vector<int>> result;
    for (std::size_t a = 0; a < adjacent.size(); ++a) {
        if (adjacent[a].size() == 2)
            continue;
        for (const int first : adjacent[a]) {
            std::vector<int> chain{int(a), first};
            while (adjacent[std::size_t(chain.back())].size() == 2) {
                const auto& two = adjacent[std::size_t(chain.back())];
                chain.push_back(two[0] == chain[chain.size() - 2] ? two[1] : two[0]);
            }
            if (chain.front() < chain.back())
                result.push_back(std::move(chain));
        }
    }
    return result;
}

// Whether the chain's ends are joined only through the chain (its first edge is a bridge).
bool isBridge(const std::vector<int>& chain, const std::vector<std::vector<int>>& adjacent)
{
    std::vector<char> seen(adjacent.size(), 0);
    std::vector<int> stack{chain.front()};
    seen[std::size_t(chain.front())] = 1;
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        for (const int m : adjacent[std::size_t(n)]) {
            if ((n == chain[0] && m == chain[1]) || seen[std::size_t(m)])
                continue;
            if (m == chain.back())
                return false;
            seen[std::size_t(m)] = 1;
            stack.push_back(m);
        }
    }
    return true;
}

std::vector<std::vector<int>> bridgeChains(const CurveSkeleton& curve)
{
    const std::vector<std::vector<int>> adjacent = neighbours(curve);
    std::vector<std::vector<int>> result;
    for (std::vector<int>& chain : chains(adjacent))
        if (isBridge(chain, adjacent))
            result.push_back(std::move(chain));
    return result;
}

// The chain's interior nodes laid along the medial path between its ends: more of them
// where the steps would exceed `spacing`. None when it cannot be routed inside.
std::optional<std::vector<glm::dvec3>> routedInterior(const std::vector<int>& chain, const CurveSkeleton& curve,
                                                      const MedialGraph& graph, const PointInMesh& inside,
                                                      double spacing)
{
    const glm::dvec3 a = curve.nodes[std::size_t(chain.front())], b = curve.nodes[std::size_t(chain.back())];
    const auto from = attachments(a, graph, inside), to = attachments(b, graph, inside);
    if (from.empty() || to.empty())
        return std::nullopt;
    const std::vector<std::uint32_t> path = cheapestPath(graph.steps, from, to);
    if (path.empty())
        return std::nullopt;
    std::vector<glm::dvec3> polyline{a};
    for (const std::uint32_t i : path)
        polyline.push_back(graph.points[i]);
    polyline.push_back(b);
    smooth(polyline);
    double length = 0.0;
    for (std::size_t i = 1; i < polyline.size(); ++i)
        length += glm::length(polyline[i] - polyline[i - 1]);
    const std::size_t interior = chain.size() - 2;
    const std::size_t count = std::max(interior, std::size_t(std::max(0.0, std::ceil(length / spacing) - 1.0)));
    if (count == 0)
        return std::nullopt;
    std::vector<glm::dvec3> nodes = spreadAlong(polyline, count);
    glm::dvec3 previous = a;
    for (const glm::dvec3& p : nodes) {
        if (!inside.segmentInside(previous, p))
            return std::nullopt;
        previous = p;
    }
    if (!inside.segmentInside(previous, b))
        return std::nullopt;
    return nodes;
}

// Replaces the chain's edges by the path through `positions`: the old interior nodes in
// their order on evenly spread slots, the other slots new nodes.
void replaceChain(CurveSkeleton& curve, const std::vector<int>& chain, const std::vector<glm::dvec3>& positions,
                  std::set<std::array<int, 2>>& edges)
{
    const std::size_t interior = chain.size() - 2, count = positions.size();
    std::vector<int> slots(count, -1);
    for (std::size_t k = 0; k < interior; ++k) {
        const auto slot = std::size_t(std::llround(double(k + 1) * double(count + 1) / double(interior + 1))) - 1;
        slots[std::min(slot, count - 1)] = chain[k + 1];
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (slots[i] < 0) {
            slots[i] = int(curve.nodes.size());
            curve.nodes.push_back(positions[i]);
        } else {
            curve.nodes[std::size_t(slots[i])] = positions[i];
        }
    }
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        edges.erase({std::min(chain[i], chain[i + 1]), std::max(chain[i], chain[i + 1])});
    int previous = chain.front();
    for (std::size_t i = 0; i <= count; ++i) {
        const int next = i < count ? slots[i] : chain.back();
        edges.insert({std::min(previous, next), std::max(previous, next)});
        previous = next;
    }
}

} // namespace

std::vector<char> routableChainInteriors(const CurveSkeleton& curve)
{
    std::vector<char> interior(curve.nodes.size(), 0);
    for (const std::vector<int>& chain : bridgeChains(curve))
        for (std::size_t i = 1; i + 1 < chain.size(); ++i)
            interior[std::size_t(chain[i])] = 1;
    return interior;
}

ChainRouting routeChainsAlongMedialAxis(CurveSkeleton& curve, const TriangleMesh& mesh,
                                        const std::vector<std::optional<glm::dvec3>>& midpoints,
                                        const PointInMesh& inside, double spacing)
{
    if (curve.vertexNode.size() != mesh.positions.size() || midpoints.size() != mesh.positions.size())
        throw std::invalid_argument(
            "routing the skeleton's chains needs one node and one chord midpoint per mesh vertex (" +
            std::to_string(mesh.positions.size()) + " vertices, " + std::to_string(curve.vertexNode.size()) +
            " nodes, " + std::to_string(midpoints.size()) + " midpoints)");
    if (!(spacing > 0.0) || !std::isfinite(spacing))
        throw std::invalid_argument("routing the skeleton's chains needs a positive spacing");

    const std::vector<std::vector<int>> routable = bridgeChains(curve);
    if (routable.empty() || mesh.positions.empty())
        return {0, std::vector<char>(curve.nodes.size(), 0)};

    const MedialGraph graph = medialGraph(mesh, midpoints, 0.5 * spacing);
    std::vector<std::optional<std::vector<glm::dvec3>>> routed(routable.size());
    parallelFor(routable.size(), 0,
                [&](std::size_t c) { routed[c] = routedInterior(routable[c], curve, graph, inside, spacing); });
    auto withRouted = [&] {
        CurveSkeleton result = curve;
        std::set<std::array<int, 2>> edges(curve.edges.begin(), curve.edges.end());
        for (std::size_t c = 0; c < routable.size(); ++c)
            if (routed[c])
                replaceChain(result, routable[c], *routed[c], edges);
        result.edges.assign(edges.begin(), edges.end());
        return result;
    };
    CurveSkeleton candidate = withRouted();

    // A chain that folds (up into a head and back to a junction beside where it started)
    // covers what the cheapest path between its ends cuts off, and a chain that zig-zags
    // through a flat part covers more of it than its middle does. Where the vertices a
    // routed chain's nodes absorbed end farther from the whole curve than before — beyond
    // the tolerance and beyond the worst-covered vertex of the mesh — that chain stays as
    // it was; and if the worst-covered vertex itself ends farther, no chain is routed.
    const double step = kCoverageSampling * spacing;
    const std::vector<double> before = distancesToCurveSamples(mesh.positions, curve, step);
    std::vector<double> after = distancesToCurveSamples(mesh.positions, candidate, step);
    const double worstBefore = *std::max_element(before.begin(), before.end());
    std::vector<int> chainOfNode(curve.nodes.size(), -1);
    for (std::size_t c = 0; c < routable.size(); ++c)
        for (std::size_t i = 1; i + 1 < routable[c].size(); ++i)
            chainOfNode[std::size_t(routable[c][i])] = int(c);
    std::vector<double> farthestBefore(routable.size(), 0.0), farthestAfter(routable.size(), 0.0);
    for (std::size_t v = 0; v < curve.vertexNode.size(); ++v) {
        const int node = curve.vertexNode[v];
        if (node < 0 || std::size_t(node) >= chainOfNode.size() || chainOfNode[std::size_t(node)] < 0)
            continue;
        const auto c = std::size_t(chainOfNode[std::size_t(node)]);
        farthestBefore[c] = std::max(farthestBefore[c], before[v]);
        farthestAfter[c] = std::max(farthestAfter[c], after[v]);
    }
    bool dropped = false;
    for (std::size_t c = 0; c < routable.size(); ++c)
        if (routed[c] && farthestAfter[c] > std::max(kCoverageTolerance * farthestBefore[c], worstBefore)) {
            routed[c].reset();
            dropped = true;
        }
    if (dropped) {
        candidate = withRouted();
        after = distancesToCurveSamples(mesh.positions, candidate, step);
    }
    if (*std::max_element(after.begin(), after.end()) > kCoverageTolerance * worstBefore)
        return {0, std::vector<char>(curve.nodes.size(), 0)};

    ChainRouting result;
    result.placed.assign(candidate.nodes.size(), 0);
    std::fill(result.placed.begin() + std::ptrdiff_t(curve.nodes.size()), result.placed.end(), 1); // added nodes
    for (std::size_t c = 0; c < routable.size(); ++c)
        if (routed[c]) {
            ++result.chains;
            for (std::size_t i = 1; i + 1 < routable[c].size(); ++i)
                result.placed[std::size_t(routable[c][i])] = 1;
        }
    curve = std::move(candidate);
    return result;
}

} // namespace trimlab
