#include "core/skeleton/cap_bones.h"

#include "core/skeleton/half_sphere_directions.h"
#include "core/skeleton/leaf_extension.h"
#include "core/skeleton/skeleton_centring.h"
#include "core/skeleton/skeleton_evaluation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

namespace trimlab {

namespace {

// Region vertices fewer than this make no cap (a bump of the tessellation).
constexpr std::size_t kMinCapVertices = 8;
// Antipodal ray pairs that find a node's nearest wall.
constexpr int kWallDirections = 48;
// Halvings of a cap bone that would leave the solid before it is given up.
constexpr int kShrinkSteps = 4;
// Moves of a new leaf across its bone (centreLeavesAcrossTheirBones's default).
constexpr int kCentringRounds = CentringOptions{}.rounds;

struct Cap {
    std::size_t node = 0;
    glm::dvec3 direction{0.0};
    double step = 0.0;     ///< the leaf extension's length: reach − local radius
    double farthest = 0.0; ///< the region's largest distance to the curve
};

// The cap ahead of node k, if its region has one that no bone of k reaches (see the
// header): its direction is that of the region's far vertices (distance[v] ≥ band), its
// width that of the region's part ahead of the node.
std::optional<Cap> capAhead(const CurveSkeleton& curve, std::size_t k, const std::vector<int>& neighbours,
                            const std::vector<std::size_t>& region, const TriangleMesh& mesh,
                            const std::vector<double>& distance, double band)
{
    const glm::dvec3 node = curve.nodes[k];
    glm::dvec3 centroid(0.0);
    std::size_t far = 0;
    for (std::size_t v : region)
        if (distance[v] >= band) {
            centroid += glm::dvec3(mesh.positions[v]);
            ++far;
        }
    if (far == 0)
        return std::nullopt;
    centroid /= static_cast<double>(far);
    const double ahead = glm::length(centroid - node);
    if (ahead == 0.0)
        return std::nullopt;
    const glm::dvec3 direction = (centroid - node) / ahead;
    for (int j : neighbours) {
        const glm::dvec3 bone = curve.nodes[static_cast<std::size_t>(j)] - node;
        if (glm::length(bone) > 0.0 && glm::dot(glm::normalize(bone), direction) >= kCapBoneCone)
            return std::nullopt;
    }
    std::vector<std::size_t> front;
    for (std::size_t v : region)
        if (glm::dot(glm::dvec3(mesh.positions[v]) - node, direction) > 0.0)
            front.push_back(v);
    const RegionReach reach = regionReach(front, mesh, node, direction);
    if (ahead <= reach.radius || reach.ahead <= reach.radius)
        return std::nullopt; // far vertices around the node, or within the cap's own radius
    return Cap{k, direction, reach.ahead - reach.radius, 0.0};
}

// The region's largest distance to the curve with the bone from `node` to `tip` added.
double farthestWithBone(const std::vector<std::size_t>& region, const std::vector<double>& distance,
                        const TriangleMesh& mesh, const glm::dvec3& node, const glm::dvec3& tip)
{
    double farthest = 0.0;
    for (std::size_t v : region)
        farthest = std::max(farthest, std::min(distance[v], segmentDistance(glm::dvec3(mesh.positions[v]), node, tip)));
    return farthest;
}

// The distance from p to its nearest wall, over antipodal ray pairs (infinity where none
// finds a wall).
double nearestWall(const glm::dvec3& p, const PointInMesh& solid, const std::vector<glm::dvec3>& directions)
{
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& d : directions)
        for (const glm::dvec3& ray : {d, -d})
            if (const std::optional<double> t = solid.nearestCrossing(p, ray, 0.0, nearest))
                nearest = std::min(nearest, *t);
    return nearest;
}

} // namespace

std::size_t addCapBones(CurveSkeleton& curve, const TriangleMesh& mesh, const PointInMesh& solid)
{
    const std::size_t nodeCount = curve.nodes.size();
    std::vector<std::vector<int>> neighbours(nodeCount);
    for (const auto& edge : curve.edges) {
        neighbours[static_cast<std::size_t>(edge[0])].push_back(edge[1]);
        neighbours[static_cast<std::size_t>(edge[1])].push_back(edge[0]);
    }
    std::vector<std::vector<std::size_t>> regions(nodeCount);
    for (std::size_t v = 0; v < curve.vertexNode.size() && v < mesh.vertexCount(); ++v)
        if (const int k = curve.vertexNode[v]; k >= 0 && static_cast<std::size_t>(k) < nodeCount)
            regions[static_cast<std::size_t>(k)].push_back(v);

    std::vector<double> distance = distancesToSkeleton(mesh.positions, skeletonGraph(curve));
    const double meshFarthest = distance.empty() ? 0.0 : *std::max_element(distance.begin(), distance.end());
    const double band = kCapWorstFraction * meshFarthest;
    const auto regionFarthest = [&](std::size_t k) {
        double farthest = 0.0;
        for (std::size_t v : regions[k])
            farthest = std::max(farthest, distance[v]);
        return farthest;
    };
    const std::vector<glm::dvec3> directions = halfSphereDirections(kWallDirections);
    std::vector<Cap> caps;
    for (std::size_t k = 0; k < nodeCount; ++k) {
        if (neighbours[k].size() < 2 || regions[k].size() < kMinCapVertices)
            continue;
        const double farthest = regionFarthest(k);
        if (farthest < band)
            continue;
        std::optional<Cap> cap = capAhead(curve, k, neighbours[k], regions[k], mesh, distance, band);
        // A junction's nearest wall (96 rays) only for a cap: as near as its ball reaches
        // is a round end (a ball-shaped hub between limbs).
        if (!cap ||
            (neighbours[k].size() >= 3 && farthest <= kCapBallRatio * nearestWall(curve.nodes[k], solid, directions)))
            continue;
        cap->farthest = farthest;
        caps.push_back(*cap);
    }
    std::sort(caps.begin(), caps.end(), [](const Cap& a, const Cap& b) { return a.farthest > b.farthest; });

    std::size_t added = 0;
    for (const Cap& cap : caps) {
        const std::vector<std::size_t>& region = regions[cap.node];
        const glm::dvec3 node = curve.nodes[cap.node];
        // Again: a bone added before may have brought this region's far vertices nearer
        // (one bone per cap, not one per node of a chain beside it).
        const double before = regionFarthest(cap.node);
        if (before < band)
            continue;
        double step = cap.step;
        for (int attempt = 0; attempt <= kShrinkSteps; ++attempt, step *= 0.5) {
            glm::dvec3 tip = node + step * cap.direction;
            if (!solid.segmentInside(node, tip))
                continue;
            if (farthestWithBone(region, distance, mesh, node, tip) > (1.0 - kMinCapGain) * before)
                break; // a shorter bone would gain less
            tip = leafCentredAcrossItsBone(node, tip, solid, kCentringRounds);
            const int leaf = static_cast<int>(curve.nodes.size());
            curve.nodes.push_back(tip);
            curve.edges.push_back({static_cast<int>(cap.node), leaf});
            for (std::size_t v = 0; v < distance.size(); ++v)
                distance[v] = std::min(distance[v], segmentDistance(glm::dvec3(mesh.positions[v]), node, tip));
            const glm::dvec3 along = tip - node;
            for (std::size_t v : region)
                if (glm::dot(glm::dvec3(mesh.positions[v]) - node, along) > 0.5 * glm::dot(along, along))
                    curve.vertexNode[v] = leaf;
            ++added;
            break;
        }
    }
    std::sort(curve.edges.begin(), curve.edges.end());
    return added;
}

} // namespace trimlab
