#include "core/skeleton/branch_recovery.h"

#include "core/skeleton/mesh_adjacency.h"
#include "core/skeleton/shrinking_balls.h"
#include "core/skeleton/skeleton_evaluation.h"
#include "core/util/union_find.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

namespace trimlab {

namespace {

/// Nearest skeleton nodes tried for the branch's attachment before the branch is dropped.
constexpr std::size_t kAttachmentTries = 8;

/// Surface path length from the patch's border with the covered surface, within the patch
/// (Dijkstra over mesh edges); infinity where no border is reachable.
std::map<std::size_t, double> depthsFromBorder(const std::vector<std::size_t>& patch,
                                               const std::vector<char>& uncovered, const VertexAdjacency& adjacency)
{
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    std::map<std::size_t, double> depth;
    for (std::size_t v : patch) {
        depth[v] = std::numeric_limits<double>::infinity();
        for (const auto& [w, length] : adjacency[v])
            if (!uncovered[w]) {
                depth[v] = 0.0;
                queue.emplace(0.0, v);
                break;
            }
    }
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > depth[v])
            continue;
        for (const auto& [w, length] : adjacency[v]) {
            if (!uncovered[w])
                continue;
            const double next = d + length;
            if (next < depth[w]) {
                depth[w] = next;
                queue.emplace(next, w);
            }
        }
    }
    return depth;
}

/// One connected piece of a slice of a patch: its vertices, the centre its node takes, and
/// the piece of the slice before it that it continues (an index into the patch's pieces;
/// -1 for the pieces of the first slice, which join the skeleton).
struct Slice {
    std::vector<std::size_t> vertices;
    glm::dvec3 centreSum{0.0};
    int parent = -1;
};

/// The slice's node: the mean of its ball centres if that is inside, else the ball centre
/// nearest to that mean (ball centres are inside).
glm::dvec3 sliceNode(const Slice& slice, const std::vector<std::optional<glm::dvec3>>& ballCentres,
                     const PointInMesh& solid)
{
    const glm::dvec3 mean = slice.centreSum / double(slice.vertices.size());
    if (solid.contains(mean))
        return mean;
    glm::dvec3 nearest = *ballCentres[slice.vertices.front()];
    for (std::size_t v : slice.vertices)
        if (glm::length(*ballCentres[v] - mean) < glm::length(nearest - mean))
            nearest = *ballCentres[v];
    return nearest;
}

/// The existing node nearest to `p` whose segment to p lies inside, among the
/// kAttachmentTries nearest; -1 when none.
int attachmentNode(const CurveSkeleton& curve, std::size_t existingNodes, const glm::dvec3& p, const PointInMesh& solid)
{
    std::vector<std::pair<double, int>> byDistance;
    for (std::size_t k = 0; k < existingNodes; ++k)
        byDistance.emplace_back(glm::length(curve.nodes[k] - p), int(k));
    const std::size_t tries = std::min(kAttachmentTries, byDistance.size());
    std::partial_sort(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(tries), byDistance.end());
    for (std::size_t i = 0; i < tries; ++i)
        if (solid.segmentInside(curve.nodes[std::size_t(byDistance[i].second)], p))
            return byDistance[i].second;
    return -1;
}

/// The vertices' medial balls where they were needed, and which vertices are uncovered.
struct Coverage {
    std::vector<char> uncovered;
    std::vector<std::optional<glm::dvec3>> ballCentres; ///< known near the patches only
    std::vector<double> radius;                         ///< of the known balls
};

Coverage uncoveredVertices(const TriangleMesh& mesh, const std::vector<std::optional<glm::dvec3>>& midpoints,
                           const std::vector<double>& distance, const VertexAdjacency& adjacency,
                           const ShrinkingBalls& balls)
{
    Coverage c{std::vector<char>(mesh.vertexCount(), 0), std::vector<std::optional<glm::dvec3>>(mesh.vertexCount()),
               std::vector<double>(mesh.vertexCount(), 0.0)};
    // Seeds without any ball: the chord's half-length bounds the ball's radius from above
    // (the ball starts as the chord's ball and only shrinks), so a vertex farther than
    // kUncoveredRatio half-chords is uncovered whatever its ball. Covered parts — most of
    // the mesh — need no ball then.
    std::vector<std::size_t> grow;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        if (midpoints[v] &&
            distance[v] > kUncoveredRatio * glm::length(*midpoints[v] - glm::dvec3(mesh.positions[v]))) {
            c.uncovered[v] = 1;
            grow.push_back(v);
        }
    // Then the patches grow over neighbours whose ball says they are uncovered: a limb's
    // tip, whose chord runs back along the limb, is uncovered by its ball (the cap's).
    std::vector<char> ballKnown(mesh.vertexCount(), 0);
    const auto knowBall = [&](std::size_t v) {
        if (ballKnown[v])
            return;
        ballKnown[v] = 1;
        c.ballCentres[v] = balls.centre(v);
        if (c.ballCentres[v])
            c.radius[v] = glm::length(*c.ballCentres[v] - glm::dvec3(mesh.positions[v]));
    };
    while (!grow.empty()) {
        const std::size_t v = grow.back();
        grow.pop_back();
        knowBall(v);
        for (const auto& [w, length] : adjacency[v]) {
            if (c.uncovered[w] || ballKnown[w])
                continue;
            knowBall(w);
            if (c.ballCentres[w] && distance[w] > kUncoveredRatio * c.radius[w]) {
                c.uncovered[w] = 1;
                grow.push_back(w);
            }
        }
    }
    return c;
}

/// The connected patches of uncovered vertices (over mesh edges).
std::vector<std::vector<std::size_t>> uncoveredPatches(const TriangleMesh& mesh, const std::vector<char>& uncovered)
{
    UnionFind patches(mesh.vertexCount());
    for (const glm::uvec3& t : mesh.triangles)
        for (int i = 0; i < 3; ++i)
            if (uncovered[t[i]] && uncovered[t[(i + 1) % 3]])
                patches.unite(t[i], t[(i + 1) % 3]);
    std::map<std::size_t, std::vector<std::size_t>> byRoot;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        if (uncovered[v])
            byRoot[patches.find(v)].push_back(v);
    std::vector<std::vector<std::size_t>> out;
    for (auto& [root, patch] : byRoot)
        out.push_back(std::move(patch));
    return out;
}

/// A last piece with fewer than 1/kFringeRatio of the vertices of the piece before it
/// joins that piece (limbSlices).
constexpr std::size_t kFringeRatio = 8;

/// The connected pieces of the slices (vertices with the same `sliceOf`, joined by mesh
/// edges), ordered by slice, each with the piece of the slice before that it shares most
/// mesh edges with as its parent.
std::vector<Slice> slicePieces(const std::map<std::size_t, std::size_t>& sliceOf, const Coverage& c,
                               const VertexAdjacency& adjacency)
{
    std::map<std::size_t, std::size_t> local; // patch vertex -> index in `vertices`
    std::vector<std::size_t> vertices;
    for (const auto& [v, slice] : sliceOf) {
        local[v] = vertices.size();
        vertices.push_back(v);
    }
    // Two vertices of a slice are in one piece when a mesh edge joins them, or when both
    // neighbour one vertex of that slice or of the slices beside it: a slice about an edge
    // wide is a band whose vertices often meet only across a vertex of the next slice.
    UnionFind pieces(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const std::size_t slice = sliceOf.at(vertices[i]);
        std::map<std::size_t, std::size_t> firstOfSlice; // among i's neighbours
        for (const auto& [w, length] : adjacency[vertices[i]]) {
            const auto found = sliceOf.find(w);
            if (found == sliceOf.end())
                continue;
            if (found->second == slice)
                pieces.unite(i, local.at(w));
            if (found->second + 1 >= slice && found->second <= slice + 1) {
                const auto [first, added] = firstOfSlice.try_emplace(found->second, local.at(w));
                if (!added)
                    pieces.unite(first->second, local.at(w));
            }
        }
    }
    // Pieces ordered by slice, then by their first vertex: the same order every run.
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> members; // (slice, root) -> vertices
    std::vector<std::size_t> pieceOfVertex(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        members[{sliceOf.at(vertices[i]), pieces.find(i)}].push_back(i);
    std::vector<std::pair<std::size_t, std::vector<std::size_t>>> ordered; // (slice, members)
    for (auto& [key, list] : members)
        ordered.emplace_back(key.first, std::move(list));
    std::stable_sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second.front() < b.second.front();
    });
    std::vector<Slice> result(ordered.size());
    for (std::size_t p = 0; p < ordered.size(); ++p)
        for (std::size_t i : ordered[p].second) {
            pieceOfVertex[i] = p;
            result[p].vertices.push_back(vertices[i]);
            result[p].centreSum += *c.ballCentres[vertices[i]];
        }
    for (std::size_t p = 0; p < ordered.size(); ++p) {
        std::map<std::size_t, int> shared; // piece of the slice before -> mesh edges to it
        for (std::size_t i : ordered[p].second)
            for (const auto& [w, length] : adjacency[vertices[i]])
                if (const auto found = sliceOf.find(w); found != sliceOf.end() && found->second + 1 == ordered[p].first)
                    ++shared[pieceOfVertex[local.at(w)]];
        int most = 0;
        for (const auto& [piece, edges] : shared)
            if (edges > most) {
                most = edges;
                result[p].parent = int(piece);
            }
    }
    return result;
}

/// A patch's slices by depth, cut into their connected pieces (where a limb forks — a
/// head's two ears — a slice has a piece in each fork), base first; none when the patch is
/// too small or shallow to be a limb.
std::vector<Slice> limbSlices(const std::vector<std::size_t>& patch, const Coverage& c,
                              const VertexAdjacency& adjacency, double spacing)
{
    if (patch.size() < kMinPatchVertices)
        return {};
    const std::map<std::size_t, double> depth = depthsFromBorder(patch, c.uncovered, adjacency);
    double deepest = 0.0, meanRadius = 0.0;
    std::size_t withBall = 0;
    for (std::size_t v : patch) {
        if (std::isfinite(depth.at(v)))
            deepest = std::max(deepest, depth.at(v));
        if (c.ballCentres[v]) {
            meanRadius += c.radius[v];
            ++withBall;
        }
    }
    if (withBall == 0)
        return {};
    meanRadius /= double(withBall);
    const double width = std::max(spacing, meanRadius);
    if (deepest < kMinDepthRatio * meanRadius || !(width > 0.0))
        return {};
    std::map<std::size_t, std::size_t> sliceOf;
    for (std::size_t v : patch)
        if (std::isfinite(depth.at(v)) && c.ballCentres[v])
            sliceOf[v] = std::size_t(depth.at(v) / width);
    std::vector<Slice> slices = slicePieces(sliceOf, c, adjacency);
    // A last piece far smaller than the one before it is a fringe, not a section: where
    // the limb's end is flat or slanted (the hand's wrist, cut square), the surface path
    // from the patch's base is longest to one rim of the end, and the deepest slice is a
    // crescent along that rim, whose ball centres sit at the rim: a leaf there leaves the
    // far side of the end a whole width from the bone (the hand's worst vertex). Joined to
    // the piece before, the leaf is the centre of the end. A round tip's last slice is a
    // cap that this leaves alone unless it is a sliver (then it is shorter than an eighth
    // of a width and the leaf moves by less). Children come after their parents, so one
    // pass from the back joins fringes of fringes too.
    std::vector<int> children(slices.size(), 0);
    for (const Slice& slice : slices)
        if (slice.parent >= 0)
            ++children[std::size_t(slice.parent)];
    std::vector<char> joined(slices.size(), 0);
    for (std::size_t p = slices.size(); p-- > 0;) {
        const Slice& piece = slices[p];
        if (children[p] > 0 || piece.parent < 0)
            continue;
        Slice& before = slices[std::size_t(piece.parent)];
        if (kFringeRatio * piece.vertices.size() >= before.vertices.size())
            continue;
        before.vertices.insert(before.vertices.end(), piece.vertices.begin(), piece.vertices.end());
        before.centreSum += piece.centreSum;
        --children[std::size_t(piece.parent)];
        joined[p] = 1;
    }
    std::vector<Slice> kept;
    std::vector<int> renumbered(slices.size(), -1);
    for (std::size_t p = 0; p < slices.size(); ++p) {
        if (joined[p])
            continue;
        renumbered[p] = int(kept.size());
        kept.push_back(std::move(slices[p]));
        if (kept.back().parent >= 0)
            kept.back().parent = renumbered[std::size_t(kept.back().parent)];
    }
    return kept;
}

/// Appends the pieces' tree to `curve` as described in the header; true when it added at
/// least one node. A piece whose edge to its parent's node would leave the solid is left
/// out with everything beyond it.
bool addBranch(CurveSkeleton& curve, std::size_t existingNodes, const std::vector<Slice>& slices,
               const std::vector<std::optional<glm::dvec3>>& ballCentres, const PointInMesh& solid)
{
    std::vector<int> nodeOf(slices.size(), -1);
    bool added = false;
    for (std::size_t p = 0; p < slices.size(); ++p) {
        const Slice& slice = slices[p];
        const glm::dvec3 node = sliceNode(slice, ballCentres, solid);
        int previous = -1;
        if (slice.parent < 0) {
            previous = attachmentNode(curve, existingNodes, node, solid);
        } else if (const int parentNode = nodeOf[std::size_t(slice.parent)];
                   parentNode >= 0 && solid.segmentInside(curve.nodes[std::size_t(parentNode)], node)) {
            previous = parentNode;
        }
        if (previous < 0)
            continue;
        const int k = int(curve.nodes.size());
        curve.nodes.push_back(node);
        curve.edges.push_back({std::min(previous, k), std::max(previous, k)});
        for (std::size_t v : slice.vertices)
            curve.vertexNode[v] = k;
        nodeOf[p] = k;
        added = true;
    }
    return added;
}

} // namespace

std::size_t recoverBranches(CurveSkeleton& curve, const TriangleMesh& mesh,
                            const std::vector<std::optional<glm::dvec3>>& midpoints, const PointInMesh& solid,
                            double spacing)
{
    if (curve.vertexNode.size() != mesh.vertexCount() || midpoints.size() != mesh.vertexCount())
        throw std::invalid_argument("recoverBranches: " + std::to_string(curve.vertexNode.size()) +
                                    " region entries and " + std::to_string(midpoints.size()) + " midpoints for " +
                                    std::to_string(mesh.vertexCount()) + " vertices");
    if (!(spacing >= 0.0))
        throw std::invalid_argument("recoverBranches: the slice spacing must not be negative");
    if (curve.nodes.empty())
        return 0;

    const VertexAdjacency adjacency = vertexAdjacency(mesh);
    const ShrinkingBalls balls(mesh, midpoints, solid);
    const Coverage coverage =
        uncoveredVertices(mesh, midpoints, distancesToSkeleton(mesh.positions, skeletonGraph(curve)), adjacency, balls);
    const std::size_t existingNodes = curve.nodes.size();
    std::size_t added = 0;
    for (const std::vector<std::size_t>& patch : uncoveredPatches(mesh, coverage.uncovered))
        if (addBranch(curve, existingNodes, limbSlices(patch, coverage, adjacency, spacing), coverage.ballCentres,
                      solid))
            ++added;
    std::sort(curve.edges.begin(), curve.edges.end());
    return added;
}

} // namespace trimlab
