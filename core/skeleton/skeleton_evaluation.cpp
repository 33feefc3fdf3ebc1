#include "core/skeleton/skeleton_evaluation.h"

#include "core/scene/scene.h"
#include "core/skeleton/half_sphere_directions.h"
#include "core/util/parallel_for.h"
#include "core/util/union_find.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace trimlab {

namespace {

constexpr std::size_t kVertexBlock = 1024;

Scene meshScene(const TriangleMesh& mesh)
{
    Scene scene;
    scene.objects.push_back(SceneObject{"evaluated mesh", mesh, glm::dmat4(1.0)});
    return scene;
}

struct MeshTopology {
    int components = 0;
    int genus = 0;
};

MeshTopology meshTopology(const TriangleMesh& mesh)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    UnionFind sets(mesh.vertexCount());
    std::vector<bool> used(mesh.vertexCount(), false);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k];
            const std::uint32_t b = t[(k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
            sets.unite(a, b);
            used[a] = true;
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    long long vertices = 0;
    int components = 0;
    for (std::size_t v = 0; v < used.size(); ++v)
        if (used[v]) {
            ++vertices;
            components += sets.find(v) == v ? 1 : 0;
        }
    const long long euler =
        vertices - static_cast<long long>(edges.size()) + static_cast<long long>(mesh.triangleCount());
    return {components, static_cast<int>((2 * components - euler) / 2)};
}

void requireValidGraph(const SkeletonGraph& skeleton)
{
    for (std::size_t i = 0; i < skeleton.nodes.size(); ++i) {
        const glm::dvec3& p = skeleton.nodes[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw std::invalid_argument("skeleton node " + std::to_string(i) + " has a non-finite position");
    }
    const int count = static_cast<int>(skeleton.nodes.size());
    for (std::size_t e = 0; e < skeleton.edges.size(); ++e)
        for (int end : skeleton.edges[e])
            if (end < 0 || end >= count)
                throw std::invalid_argument("skeleton edge " + std::to_string(e) + " names node " +
                                            std::to_string(end) + " of " + std::to_string(count));
}

struct EdgeSample {
    glm::dvec3 position;
    double weight = 0.0; // the length it stands for
    int edge = -1;
};

std::vector<EdgeSample> edgeSamples(const SkeletonGraph& skeleton, double spacing)
{
    std::vector<EdgeSample> samples;
    for (std::size_t e = 0; e < skeleton.edges.size(); ++e) {
        const glm::dvec3 a = skeleton.nodes[static_cast<std::size_t>(skeleton.edges[e][0])];
        const glm::dvec3 b = skeleton.nodes[static_cast<std::size_t>(skeleton.edges[e][1])];
        const double length = glm::length(b - a);
        const int n = std::max(1, static_cast<int>(std::ceil(length / spacing)));
        for (int k = 0; k < n; ++k)
            samples.push_back({a + (b - a) * ((k + 0.5) / n), length / n, static_cast<int>(e)});
    }
    return samples;
}

struct GraphTopology {
    int components = 0;
    int cycles = 0;
};

GraphTopology graphTopology(const SkeletonGraph& skeleton)
{
    UnionFind sets(skeleton.nodes.size());
    for (const auto& edge : skeleton.edges)
        sets.unite(static_cast<std::size_t>(edge[0]), static_cast<std::size_t>(edge[1]));
    int components = 0;
    for (std::size_t i = 0; i < skeleton.nodes.size(); ++i)
        components += sets.find(i) == i ? 1 : 0;
    const int cycles = static_cast<int>(skeleton.edges.size()) - static_cast<int>(skeleton.nodes.size()) + components;
    return {components, cycles};
}

} // namespace

double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 ab = b - a;
    const double lengthSquared = glm::dot(ab, ab);
    const double t = lengthSquared > 0.0 ? std::clamp(glm::dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

std::vector<double> distancesToSkeleton(std::span<const glm::vec3> positions, const SkeletonGraph& skeleton)
{
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    std::vector<int> degree(skeleton.nodes.size(), 0);
    for (const auto& edge : skeleton.edges) {
        segments.emplace_back(skeleton.nodes[static_cast<std::size_t>(edge[0])],
                              skeleton.nodes[static_cast<std::size_t>(edge[1])]);
        ++degree[static_cast<std::size_t>(edge[0])];
        ++degree[static_cast<std::size_t>(edge[1])];
    }
    for (std::size_t i = 0; i < skeleton.nodes.size(); ++i)
        if (degree[i] == 0)
            segments.emplace_back(skeleton.nodes[i], skeleton.nodes[i]);
    std::vector<double> distance(positions.size(), std::numeric_limits<double>::infinity());
    const std::size_t blocks = (positions.size() + kVertexBlock - 1) / kVertexBlock;
    parallelFor(blocks, 0, [&](std::size_t block) {
        const std::size_t end = std::min(positions.size(), (block + 1) * kVertexBlock);
        for (std::size_t v = block * kVertexBlock; v < end; ++v) {
            const glm::dvec3 p(positions[v]);
            for (const auto& [a, b] : segments)
                distance[v] = std::min(distance[v], segmentDistance(p, a, b));
        }
    });
    return distance;
}

SkeletonGraph skeletonGraph(const CurveSkeleton& curve)
{
    return {curve.nodes, curve.edges};
}

SkeletonGraph skeletonGraph(const SkeletonRig& rig)
{
    SkeletonGraph graph{rig.joints, {}};
    for (const Bone& bone : rig.bones)
        graph.edges.push_back({std::min(bone.head, bone.tail), std::max(bone.head, bone.tail)});
    return graph;
}

std::vector<std::string> describeEvaluation(const SkeletonEvaluation& e)
{
    const auto format = [](const char* pattern, auto... values) {
        char line[256];
        std::snprintf(line, sizeof line, pattern, values...);
        return std::string(line);
    };
    const auto plural = [](int n, const char* one, const char* many) { return n == 1 ? one : many; };
    return {
        format("inside: %.1f %% of %d nodes, %.1f %% of %d edge samples; %.2f %% of the length outside, %d %s leaving "
               "the solid",
               100.0 * e.nodesInside, e.nodeCount, 100.0 * e.samplesInside, e.samples, 100.0 * e.lengthOutside,
               e.edgesLeaving, plural(e.edgesLeaving, "edge", "edges")),
        format("centring: asymmetry %.3f (shortest chord), %.3f (nearest wall); 0 = centred, 1 = on the surface",
               e.meanAsymmetry, e.meanWallAsymmetry),
        format("coverage: every vertex within %.4f of a bone (mean %.4f) x the diagonal; %d %s, %d %s (mesh genus %d)",
               e.maxCoverage, e.meanCoverage, e.components, plural(e.components, "component", "components"), e.cycles,
               plural(e.cycles, "cycle", "cycles"), e.meshGenus),
    };
}

SkeletonEvaluator::SkeletonEvaluator(const TriangleMesh& mesh, SkeletonEvaluationOptions options)
    : m_mesh(mesh),
      m_options(options),
      m_winding(meshScene(mesh)),
      m_solid(mesh),
      m_directions(halfSphereDirections(std::max(1, options.chordDirections)))
{
    const Bounds bounds = computeBounds(mesh);
    m_diagonal = bounds.valid() ? glm::length(bounds.max - bounds.min) : 0.0;
    const MeshTopology topology = meshTopology(mesh);
    m_meshComponents = topology.components;
    m_meshGenus = topology.genus;
}

SkeletonEvaluator::Centring SkeletonEvaluator::centring(const glm::dvec3& p) const
{
    const auto nearest = [&](const glm::dvec3& direction) {
        return m_solid.nearestCrossing(p, direction, 0.0).value_or(std::numeric_limits<double>::infinity());
    };
    const auto asymmetryOf = [](double a, double b) { return a + b > 0.0 ? std::abs(a - b) / (a + b) : 1.0; };
    double shortestChord = std::numeric_limits<double>::infinity();
    double nearestWall = std::numeric_limits<double>::infinity();
    Centring result;
    for (const glm::dvec3& d : m_directions) {
        const double a = nearest(d);
        const double b = nearest(-d);
        if (!std::isfinite(a) || !std::isfinite(b))
            continue;
        if (a + b < shortestChord) {
            shortestChord = a + b;
            result.shortestChord = asymmetryOf(a, b);
        }
        if (std::min(a, b) < nearestWall) {
            nearestWall = std::min(a, b);
            result.nearestWall = asymmetryOf(a, b);
        }
    }
    return result;
}

SkeletonEvaluation SkeletonEvaluator::evaluate(const SkeletonGraph& skeleton) const
{
    requireValidGraph(skeleton);
    SkeletonEvaluation result;
    result.nodeCount = static_cast<int>(skeleton.nodes.size());
    result.edgeCount = static_cast<int>(skeleton.edges.size());
    result.diagonal = m_diagonal;
    result.meshComponents = m_meshComponents;
    result.meshGenus = m_meshGenus;
    const double unit = m_diagonal > 0.0 ? m_diagonal : 1.0;

    // Nodes and edge samples are classified and centred alike: one list of points.
    const std::vector<EdgeSample> samples = edgeSamples(skeleton, m_options.sampleSpacing * unit);
    std::vector<glm::dvec3> points = skeleton.nodes;
    for (const EdgeSample& s : samples)
        points.push_back(s.position);
    std::vector<char> inside(points.size(), 0);
    std::vector<Centring> centred(points.size());
    parallelFor(points.size(), 0, [&](std::size_t i) {
        inside[i] = m_winding.inside(points[i]) ? 1 : 0;
        if (inside[i])
            centred[i] = centring(points[i]);
    });

    const std::size_t nodes = skeleton.nodes.size();
    int nodesInside = 0;
    for (std::size_t i = 0; i < nodes; ++i)
        nodesInside += inside[i];
    result.nodesInside = nodes > 0 ? static_cast<double>(nodesInside) / static_cast<double>(nodes) : 1.0;

    result.samples = static_cast<int>(samples.size());
    int samplesInside = 0;
    double totalLength = 0.0;
    double outsideLength = 0.0;
    std::vector<char> edgeLeaves(skeleton.edges.size(), 0);
    for (std::size_t s = 0; s < samples.size(); ++s) {
        totalLength += samples[s].weight;
        if (inside[nodes + s]) {
            ++samplesInside;
        } else {
            outsideLength += samples[s].weight;
            edgeLeaves[static_cast<std::size_t>(samples[s].edge)] = 1;
        }
    }
    for (std::size_t e = 0; e < skeleton.edges.size(); ++e)
        for (int end : skeleton.edges[e])
            if (!inside[static_cast<std::size_t>(end)])
                edgeLeaves[e] = 1;
    result.samplesInside =
        samples.empty() ? 1.0 : static_cast<double>(samplesInside) / static_cast<double>(samples.size());
    result.length = totalLength / unit;
    result.lengthOutside = totalLength > 0.0 ? outsideLength / totalLength : 0.0;
    result.edgesLeaving = static_cast<int>(std::count(edgeLeaves.begin(), edgeLeaves.end(), 1));

    double chordSum = 0.0;
    double wallSum = 0.0;
    int insidePoints = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (inside[i]) {
            chordSum += centred[i].shortestChord;
            wallSum += centred[i].nearestWall;
            ++insidePoints;
        }
    result.meanAsymmetry = insidePoints > 0 ? chordSum / insidePoints : 1.0;
    result.meanWallAsymmetry = insidePoints > 0 ? wallSum / insidePoints : 1.0;

    // Coverage: segments, and isolated nodes as points (a graph without edges still covers).
    const std::size_t vertexCount = m_mesh.vertexCount();
    if (nodes > 0) {
        const std::vector<double> coverage = distancesToSkeleton(m_mesh.positions, skeleton);
        double sum = 0.0;
        for (std::size_t v = 0; v < vertexCount; ++v) {
            if (coverage[v] / unit > result.maxCoverage) {
                result.maxCoverage = coverage[v] / unit;
                result.worstCoveredVertex = v;
            }
            sum += coverage[v] / unit;
        }
        result.meanCoverage = vertexCount > 0 ? sum / static_cast<double>(vertexCount) : 0.0;
    }

    const GraphTopology topology = graphTopology(skeleton);
    result.components = topology.components;
    result.cycles = topology.cycles;
    return result;
}

} // namespace trimlab
