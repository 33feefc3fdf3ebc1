#include "core/skeleton/skeleton_resampling.h"

#include "core/skeleton/skeleton_refinement.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace trimlab {

namespace {

// Where a region vertex lies along the curve: the edge, and the slice of it.
struct Placement {
    int edge = -1;
    int slice = 0; // 0 … steps; 0 and steps are the edge's own nodes
};

std::vector<std::vector<int>> incidentEdges(const CurveSkeleton& curve)
{
    std::vector<std::vector<int>> incident(curve.nodes.size());
    for (std::size_t e = 0; e < curve.edges.size(); ++e)
        for (int end : curve.edges[e])
            incident[static_cast<std::size_t>(end)].push_back(static_cast<int>(e));
    return incident;
}

// The edge of `node` that `p` lies along: among the incident edges whose first half
// (from the node) p projects onto, the one nearest to p; none when p lies behind every
// edge (it is the node's own: a tip, or the inside of a junction).
Placement place(const glm::dvec3& p, int node, const CurveSkeleton& curve, const std::vector<int>& edges,
                const std::vector<int>& steps)
{
    Placement best;
    double nearest = std::numeric_limits<double>::infinity();
    const glm::dvec3 from = curve.nodes[static_cast<std::size_t>(node)];
    for (int e : edges) {
        const auto& edge = curve.edges[static_cast<std::size_t>(e)];
        const glm::dvec3 to = curve.nodes[static_cast<std::size_t>(edge[0] == node ? edge[1] : edge[0])];
        const glm::dvec3 direction = to - from;
        const double lengthSquared = glm::dot(direction, direction);
        if (lengthSquared == 0.0)
            continue;
        const double t = glm::dot(p - from, direction) / lengthSquared; // 0 at node, 1 at the other end
        if (t <= 0.0 || t > 0.5)
            continue;
        const double distance = glm::length(p - (from + t * direction));
        if (distance < nearest) {
            nearest = distance;
            const int n = steps[static_cast<std::size_t>(e)];
            const int fromNode = static_cast<int>(std::lround(t * n));
            best = {e, edge[0] == node ? fromNode : n - fromNode};
        }
    }
    return best;
}

// Bisects, up to kSplitDepth times, every edge that leaves the solid, each new node at
// the inside chord midpoint nearest to the edge's midpoint: where a limb bends sharper
// than the spacing (a knee, a horn's base) the chord of two centred nodes cuts the
// surface, and the bend's own centre is what the edge should pass through.
constexpr int kSplitDepth = 3;

void splitEdge(CurveSkeleton& curve, std::array<int, 2> edge, int depth,
               const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& inside,
               std::vector<std::array<int, 2>>& edges)
{
    const glm::dvec3 a = curve.nodes[static_cast<std::size_t>(edge[0])];
    const glm::dvec3 b = curve.nodes[static_cast<std::size_t>(edge[1])];
    if (depth == kSplitDepth || inside.segmentInside(a, b)) {
        edges.push_back(edge);
        return;
    }
    const std::optional<glm::dvec3> middle = nearestInsideMidpoint(0.5 * (a + b), midpoints, inside);
    if (!middle || glm::length(*middle - a) == 0.0 || glm::length(*middle - b) == 0.0) {
        edges.push_back(edge);
        return;
    }
    const int node = static_cast<int>(curve.nodes.size());
    curve.nodes.push_back(*middle);
    splitEdge(curve, {std::min(edge[0], node), std::max(edge[0], node)}, depth + 1, midpoints, inside, edges);
    splitEdge(curve, {std::min(edge[1], node), std::max(edge[1], node)}, depth + 1, midpoints, inside, edges);
}

} // namespace

std::size_t splitEdgesLeaving(CurveSkeleton& curve, const std::vector<std::optional<glm::dvec3>>& midpoints,
                              const PointInMesh& inside)
{
    std::vector<std::array<int, 2>> edges;
    const std::vector<std::array<int, 2>> original = curve.edges;
    const std::size_t nodes = curve.nodes.size();
    for (const auto& edge : original)
        splitEdge(curve, edge, 0, midpoints, inside, edges);
    curve.edges = std::move(edges);
    std::sort(curve.edges.begin(), curve.edges.end());
    return curve.nodes.size() - nodes;
}

CurveSkeleton resampleSkeleton(const CurveSkeleton& curve, const TriangleMesh& mesh,
                               const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& inside,
                               double spacing)
{
    if (!(spacing > 0.0))
        throw std::invalid_argument("resampleSkeleton: the spacing must be positive");
    if (curve.vertexNode.size() != mesh.vertexCount() || midpoints.size() != mesh.vertexCount())
        throw std::invalid_argument("resampleSkeleton: " + std::to_string(curve.vertexNode.size()) +
                                    " vertex nodes and " + std::to_string(midpoints.size()) + " midpoints for " +
                                    std::to_string(mesh.vertexCount()) + " vertices");
    std::vector<int> steps(curve.edges.size(), 1);
    std::vector<int> firstNew(curve.edges.size(), -1); // index of the edge's slice 1
    int nodeCount = static_cast<int>(curve.nodes.size());
    for (std::size_t e = 0; e < curve.edges.size(); ++e) {
        const double length = glm::length(curve.nodes[static_cast<std::size_t>(curve.edges[e][1])] -
                                          curve.nodes[static_cast<std::size_t>(curve.edges[e][0])]);
        steps[e] = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        if (steps[e] > 1) {
            firstNew[e] = nodeCount;
            nodeCount += steps[e] - 1;
        }
    }
    CurveSkeleton out;
    out.nodes = curve.nodes;
    out.nodes.resize(static_cast<std::size_t>(nodeCount));
    out.vertexNode = curve.vertexNode;

    // Slice the regions: vertices along a resampled edge move to its slice's node.
    const std::vector<std::vector<int>> incident = incidentEdges(curve);
    std::vector<glm::dvec3> midpointSum(static_cast<std::size_t>(nodeCount), glm::dvec3(0.0));
    std::vector<int> midpointCount(static_cast<std::size_t>(nodeCount), 0);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const int node = curve.vertexNode[v];
        if (node < 0 || node >= static_cast<int>(curve.nodes.size()))
            throw std::invalid_argument("resampleSkeleton: vertex " + std::to_string(v) + " maps to node " +
                                        std::to_string(node));
        const Placement at =
            place(glm::dvec3(mesh.positions[v]), node, curve, incident[static_cast<std::size_t>(node)], steps);
        if (at.edge < 0 || at.slice <= 0 || at.slice >= steps[static_cast<std::size_t>(at.edge)])
            continue;
        const int target = firstNew[static_cast<std::size_t>(at.edge)] + at.slice - 1;
        out.vertexNode[v] = target;
        if (midpoints[v]) {
            midpointSum[static_cast<std::size_t>(target)] += *midpoints[v];
            ++midpointCount[static_cast<std::size_t>(target)];
        }
    }

    // Place the new nodes and chain the edges.
    std::vector<std::size_t> needsFallback;
    for (std::size_t e = 0; e < curve.edges.size(); ++e) {
        const int a = curve.edges[e][0];
        const int b = curve.edges[e][1];
        const int n = steps[e];
        int previous = a;
        for (int k = 1; k < n; ++k) {
            const int node = firstNew[e] + k - 1;
            const auto i = static_cast<std::size_t>(node);
            const glm::dvec3 onEdge = curve.nodes[static_cast<std::size_t>(a)] +
                                      (static_cast<double>(k) / n) * (curve.nodes[static_cast<std::size_t>(b)] -
                                                                      curve.nodes[static_cast<std::size_t>(a)]);
            const glm::dvec3 centre =
                midpointCount[i] > 0 ? midpointSum[i] / static_cast<double>(midpointCount[i]) : onEdge;
            if (midpointCount[i] > 0 && inside.contains(centre)) {
                out.nodes[i] = centre;
            } else if (inside.contains(onEdge)) {
                out.nodes[i] = onEdge;
            } else {
                out.nodes[i] = onEdge;
                needsFallback.push_back(i);
            }
            out.edges.push_back({std::min(previous, node), std::max(previous, node)});
            previous = node;
        }
        out.edges.push_back({std::min(previous, b), std::max(previous, b)});
    }
    if (!needsFallback.empty()) {
        // The inside chord midpoint of the slice nearest to where the node would go.
        std::vector<double> nearest(static_cast<std::size_t>(nodeCount), std::numeric_limits<double>::infinity());
        std::vector<glm::dvec3> best(static_cast<std::size_t>(nodeCount));
        std::vector<char> wanted(static_cast<std::size_t>(nodeCount), 0);
        for (std::size_t i : needsFallback)
            wanted[i] = 1;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const auto i = static_cast<std::size_t>(out.vertexNode[v]);
            if (!wanted[i] || !midpoints[v])
                continue;
            const double d = glm::length(*midpoints[v] - out.nodes[i]);
            if (d < nearest[i] && inside.contains(*midpoints[v])) {
                nearest[i] = d;
                best[i] = *midpoints[v];
            }
        }
        for (std::size_t i : needsFallback) {
            if (std::isfinite(nearest[i]))
                out.nodes[i] = best[i];
            else if (const auto anywhere = nearestInsideMidpoint(out.nodes[i], midpoints, inside))
                out.nodes[i] = *anywhere;
        }
    }
    splitEdgesLeaving(out, midpoints, inside);
    std::sort(out.edges.begin(), out.edges.end());
    return out;
}

} // namespace trimlab
