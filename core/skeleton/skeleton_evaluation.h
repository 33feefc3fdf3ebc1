#pragma once
/// \file
/// How good is a curve skeleton of a closed mesh? One evaluator for any skeleton — ours
/// (the curve or the rig of skeleton_extraction.h) or another tool's (the CGAL benchmark) —
/// so that numbers compare:
/// - containment: nodes, and samples along every edge, inside the solid (fast generalized
///   winding number > ½, trim/fast_winding_number.h);
/// - centring: through each inside sample, antipodal ray pairs (±d over a fixed set of
///   directions) hit the surface at distances a and b; a pair's asymmetry |a − b| / (a + b)
///   is 0 at the chord's midpoint and 1 on the surface. Two pairs are reported: the
///   shortest chord (a + b least; the measure compared with CGAL's skeleton), and the pair
///   towards the nearest wall (a least). The shortest chord alone cannot see a sample off
///   the axis of a round tube — the shortest chord through any point of a disc is bisected
///   by it — while the nearest-wall pair reads δ/r for a sample δ off the axis of a tube of
///   radius r;
/// - coverage: each mesh vertex's distance to the nearest edge of the skeleton;
/// - topology: connected components and independent cycles of the graph against the
///   mesh's components and genus (a curve skeleton of a genus-g solid has g cycles).
/// Lengths are given as fractions of the mesh's bounding-box diagonal.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/skeleton.h"
#include "core/trim/fast_winding_number.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace trimlab {

/// A skeleton as a plain graph: node positions (the mesh's units) and undirected edges.
struct SkeletonGraph {
    std::vector<glm::dvec3> nodes;
    std::vector<std::array<int, 2>> edges;
};

[[nodiscard]] SkeletonGraph skeletonGraph(const CurveSkeleton& curve);
/// Joints as nodes, one edge per bone.
[[nodiscard]] SkeletonGraph skeletonGraph(const SkeletonRig& rig);

/// The distance from `p` to the segment from `a` to `b` (to `a` when they coincide).
[[nodiscard]] double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b);

/// Per point of `positions`, the distance to the nearest edge of `skeleton` (a node without
/// edges counts as a point); infinity for a skeleton without nodes. The evaluator's
/// coverage, and the branch recovery's test for uncovered vertices. Parallel over points.
[[nodiscard]] std::vector<double> distancesToSkeleton(std::span<const glm::vec3> positions,
                                                      const SkeletonGraph& skeleton);

struct SkeletonEvaluationOptions {
    double sampleSpacing = 0.005; ///< between samples along an edge, × the diagonal
    int chordDirections = 64;     ///< antipodal pairs tried per sample (a Fibonacci half-sphere)
};

struct SkeletonEvaluation {
    int nodeCount = 0;
    int edgeCount = 0;
    double length = 0.0;                ///< total edge length, × diagonal
    double nodesInside = 0.0;           ///< fraction of nodes inside (1 when there are none)
    int samples = 0;                    ///< edge samples (interior points of the edges)
    double samplesInside = 0.0;         ///< fraction of them inside (1 when there are none)
    double lengthOutside = 0.0;         ///< fraction of the total length whose samples lie outside
    int edgesLeaving = 0;               ///< edges with a sample or an end outside
    double meanAsymmetry = 0.0;         ///< shortest chord, mean over inside nodes and samples; 0 = centred
    double meanWallAsymmetry = 0.0;     ///< nearest-wall pair, mean over the same points
    double maxCoverage = 0.0;           ///< max over vertices of the distance to the nearest edge, × diagonal
    double meanCoverage = 0.0;          ///< its mean
    std::size_t worstCoveredVertex = 0; ///< a vertex at maxCoverage
    int components = 0;                 ///< of the graph (isolated nodes count)
    int cycles = 0;                     ///< edges − nodes + components
    int meshComponents = 0;
    int meshGenus = 0;     ///< Σ over components of (2 − χ)/2, for a closed mesh
    double diagonal = 0.0; ///< the mesh's bounding-box diagonal, in its units
};

/// The numbers on three lines for people (the verb prints them, the panel shows them):
/// "inside: …", "centring: …", "coverage: …, topology".
[[nodiscard]] std::vector<std::string> describeEvaluation(const SkeletonEvaluation& evaluation);

/// Holds the acceleration structures of one closed mesh; evaluate() is const and may run
/// for several skeletons of that mesh.
class SkeletonEvaluator {
public:
    /// `mesh` should be closed and consistently oriented (the skeleton input's check);
    /// for other meshes containment has no meaning. O(F log F).
    explicit SkeletonEvaluator(const TriangleMesh& mesh, SkeletonEvaluationOptions options = {});

    /// Throws std::invalid_argument for an edge naming a node that does not exist, or a
    /// non-finite node. Parallel over samples and vertices.
    [[nodiscard]] SkeletonEvaluation evaluate(const SkeletonGraph& skeleton) const;

    struct Centring {
        double shortestChord = 1.0; ///< asymmetry of the shortest chord through p
        double nearestWall = 1.0;   ///< asymmetry of the pair towards the nearest wall
    };
    /// The two asymmetries at `p` (see the file comment); 1 where no pair hits the surface
    /// both ways.
    [[nodiscard]] Centring centring(const glm::dvec3& p) const;

    [[nodiscard]] bool inside(const glm::dvec3& p) const { return m_winding.inside(p); }

private:
    TriangleMesh m_mesh;
    SkeletonEvaluationOptions m_options;
    FastWindingNumber m_winding;
    PointInMesh m_solid; // the ray pairs, as the centring step casts them
    std::vector<glm::dvec3> m_directions;
    double m_diagonal = 0.0;
    int m_meshComponents = 0;
    int m_meshGenus = 0;
};

} // namespace trimlab
