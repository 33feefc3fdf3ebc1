#include "core/skeleton/skeleton_extraction.h"

#include "core/skeleton/branch_recovery.h"
#include "core/skeleton/cap_bones.h"
#include "core/skeleton/contraction_solver.h"
#include "core/skeleton/point_in_mesh.h"
#include "core/skeleton/rig_hierarchy.h"
#include "core/skeleton/leaf_extension.h"
#include "core/skeleton/skeleton_centring.h"
#include "core/skeleton/medial_chain_routing.h"
#include "core/skeleton/medial_targets.h"
#include "core/skeleton/shrinking_balls.h"
#include "core/skeleton/skeleton_refinement.h"
#include "core/skeleton/skeleton_resampling.h"
#include "core/skeleton/skeleton_rerouting.h"
#include "core/skeleton/skeleton_selection.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace trimlab {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The contraction's medial points (none without a medial weight).
std::vector<std::optional<glm::dvec3>> medialPointsFor(const TriangleMesh& mesh, const ContractionOptions& options,
                                                       const std::vector<std::optional<glm::dvec3>>& midpoints,
                                                       const PointInMesh& solid)
{
    if (!(options.medialWeight > 0.0))
        return {};
    switch (options.medialPoints) {
    case MedialPoints::FilteredChordMidpoints:
        return medialTargets(mesh, midpoints);
    case MedialPoints::ShrinkingBalls:
        return shrinkingBallCentres(mesh, midpoints, solid);
    }
    return {};
}

} // namespace

namespace {

SkeletonRig selectRigInside(const CurveSkeleton& curve, const TriangleMesh& mesh, const PointInMesh& solid,
                            int targetNodes, int rootJoint)
{
    const std::vector<glm::dvec3> original(mesh.positions.begin(), mesh.positions.end());
    const NodeSelection selection = selectSkeletonNodes(curve, original, targetNodes, &solid);
    return buildSkeletonRig(curve, selection, original, rootJoint);
}

} // namespace

SkeletonRig selectRig(const CurveSkeleton& curve, const TriangleMesh& mesh, int targetNodes, int rootJoint)
{
    return selectRigInside(curve, mesh, PointInMesh(mesh), targetNodes, rootJoint);
}

SkeletonExtraction extractSkeleton(const TriangleMesh& mesh, const SkeletonOptions& options, const TaskControl& control)
{
    checkSkeletonInput(mesh);
    if (options.targetNodes < 1)
        throw std::invalid_argument("the skeleton needs a target of at least 1 node, not " +
                                    std::to_string(options.targetNodes));
    SkeletonExtraction result;

    // The inward chord midpoints serve the refinement and, with a medial weight, the
    // contraction; made once, before both, and counted in the refinement's time (where
    // they were before the medial attraction; Table III compares that column).
    Clock::time_point start = Clock::now();
    const PointInMesh solid(mesh);
    const bool needMidpoints = options.refine || options.contraction.medialWeight > 0.0;
    const std::vector<std::optional<glm::dvec3>> midpoints =
        needMidpoints ? inwardChordMidpoints(mesh, solid) : std::vector<std::optional<glm::dvec3>>{};
    const double midpointsMs = millisecondsSince(start);

    start = Clock::now();
    const std::vector<std::optional<glm::dvec3>> medial = medialPointsFor(mesh, options.contraction, midpoints, solid);
    ContractionSolver contraction(mesh, options.contraction, medial);
    contraction.run(control);
    result.contracted = contraction.positions();
    result.laplacianMagnitude = contraction.laplacianMagnitude();
    result.contractionIterations = contraction.iterations();
    result.symbolicAnalyses = contraction.symbolicAnalyses();
    result.numericFactorizations = contraction.numericFactorizations();
    result.solver = contraction.solverDescription();
    result.warnings = contraction.warnings();
    result.times.contractionMs = millisecondsSince(start);

    control.throwIfCancelled();
    start = Clock::now();
    const Bounds bounds = computeBounds(mesh);
    const double delta = options.simplification.preCollapseFraction * glm::length(bounds.max - bounds.min);
    result.curve = simplifyContractedMesh(result.contracted, mesh.triangles, delta, options.simplification, control);
    result.times.simplificationMs = millisecondsSince(start);

    control.throwIfCancelled();
    start = Clock::now();
    control.report("refinement", 0, 1);
    if (options.refine) {
        refineSkeleton(result.curve, mesh, midpoints, solid);
        if (options.resampleFraction > 0.0)
            result.curve = resampleSkeleton(result.curve, mesh, midpoints, solid,
                                            options.resampleFraction * glm::length(bounds.max - bounds.min));
        if (options.centre) {
            extendLeaves(result.curve, mesh, solid);
            centreLeavesAcrossTheirBones(result.curve, solid);
            if (options.recoverBranches)
                recoverBranches(result.curve, mesh, midpoints, solid,
                                std::max(0.0, options.resampleFraction) * glm::length(bounds.max - bounds.min));
            if (options.routeChains && options.resampleFraction > 0.0) {
                // The chains the routing replaces are centred only where it fails: the
                // junctions first (the routes' ends), then the chains left as they were.
                const std::vector<char> routable = routableChainInteriors(result.curve);
                centreOnNearestWallChords(result.curve, solid, {}, routable);
                const ChainRouting routing =
                    routeChainsAlongMedialAxis(result.curve, mesh, midpoints, solid,
                                               options.resampleFraction * glm::length(bounds.max - bounds.min));
                std::vector<char> done(routing.placed.size(), 1);
                for (std::size_t k = 0; k < routable.size(); ++k)
                    done[k] = !routable[k] || routing.placed[k];
                centreOnNearestWallChords(result.curve, solid, {}, done);
            } else {
                centreOnNearestWallChords(result.curve, solid);
            }
            addCapBones(result.curve, mesh, solid);
            splitEdgesLeaving(result.curve, midpoints, solid);
            rerouteLeavingEdges(result.curve, mesh, midpoints, solid);
        }
    }
    control.report("refinement", 1, 1);
    result.times.refinementMs = midpointsMs + millisecondsSince(start);

    control.throwIfCancelled();
    start = Clock::now();
    control.report("selection", 0, 1);
    result.rig = selectRigInside(result.curve, mesh, solid, options.targetNodes, options.rootJoint);
    control.report("selection", 1, 1);
    result.times.selectionMs = millisecondsSince(start);
    return result;
}

} // namespace trimlab
