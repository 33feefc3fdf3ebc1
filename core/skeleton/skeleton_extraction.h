#pragma once
/// \file
/// Skeleton extraction by mesh contraction (Berenguer & Moreno, after Au et al. 2008),
/// stages A–D: contraction (contraction_solver.h), simplification
/// (skeleton_simplification.h), refinement (skeleton_refinement.h) and selection
/// (skeleton_selection.h, rig_hierarchy.h). The bone-heat weights, posing and export
/// (stages E–F) consume the SkeletonRig this produces.

#include "core/util/task_control.h"
#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/contraction_options.h"
#include "core/skeleton/skeleton.h"
#include "core/skeleton/skeleton_input.h"
#include "core/skeleton/skeleton_simplification.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace trimlab {

// SparseOrdering, SparseBackend, ContractionOptions: contraction_options.h.
// SimplificationOptions: skeleton_simplification.h.

struct SkeletonOptions {
    ContractionOptions contraction;
    SimplificationOptions simplification;
    bool refine = true; ///< stage C; false keeps the nodes at their contracted positions
    /// After refinement, edges longer than this fraction of the bounding-box diagonal get
    /// centred intermediate nodes (skeleton_resampling.h); ≤ 0 leaves the curve as the
    /// simplification made it. Only with refine.
    double resampleFraction = 0.01;
    /// Last, the leaves reach out to their tips (leaf_extension.h), every node moves to the
    /// midpoint of its chord towards the nearest wall (skeleton_centring.h), and a blunt end
    /// that no leaf points at gets one (cap_bones.h). Only with refine.
    bool centre = true;
    /// After the leaves reach their tips, limbs that no branch reaches get one
    /// (branch_recovery.h). Only with refine and centre.
    bool recoverBranches = true;
    /// With the centring, every chain that is a bridge of the curve is laid along the
    /// cheapest path through the medial points between its ends
    /// (medial_chain_routing.h), spaced as the resampling's; only the chains it leaves are
    /// centred. Only with refine, centre and a positive resampleFraction.
    bool routeChains = true;
    int targetNodes = 30; ///< joints after selection; 20–40 typical (paper III.D); skeleton_parameters.h
    int rootJoint = -1;   ///< −1: automatic (rig_hierarchy.h); else a joint index of the selection

    friend bool operator==(const SkeletonOptions&, const SkeletonOptions&) = default;
};

/// Wall-clock time of each stage, in milliseconds.
struct SkeletonStageTimes {
    double contractionMs = 0, simplificationMs = 0, refinementMs = 0, selectionMs = 0;
};

struct SkeletonExtraction {
    std::vector<glm::dvec3> contracted;     ///< #V contracted positions
    std::vector<double> laplacianMagnitude; ///< #V, ‖L·V'‖ of the last iteration, for the Fig. 7 colour map
    int contractionIterations = 0;
    int symbolicAnalyses = 0, numericFactorizations = 0;
    CurveSkeleton curve; ///< simplified and refined curve skeleton
    SkeletonRig rig;     ///< selected joints, bones, hierarchy
    SkeletonStageTimes times;
    std::string solver;                ///< the factorization used, e.g. "CHOLMOD supernodal LLᵀ, METIS ordering"
    std::vector<std::string> warnings; ///< solver fallbacks, a discarded divergent iteration, ...
};

/// Runs stages A–D on `mesh`, reporting progress through `control` with the stages
/// "contraction", "simplification", "refinement" and "selection" (each reported at
/// least at its start and end) and honouring its stop token between iterations and
/// every 1024 collapses.
/// Throws SkeletonInputError (refused mesh: checkSkeletonInput) or OperationCancelled;
/// std::invalid_argument for options out of range (see ContractionOptions,
/// targetNodes < 1, rootJoint outside the selected joints); std::runtime_error if the
/// linear solver fails even after the fallback. Zero-area triangles never produce NaNs.
SkeletonExtraction extractSkeleton(const TriangleMesh& mesh, const SkeletonOptions& options,
                                   const TaskControl& control = {});

/// Re-roots / re-selects without re-contracting (the UI changes the node count or root):
/// selection and rig of `curve` (as SkeletonExtraction::curve) for `mesh`, the mesh it was
/// extracted from (its positions are the regions' original positions; its solid keeps
/// new bones inside, see skeleton_selection.h). Deterministic: with the same curve and
/// targetNodes the joints come in the same order, so a joint index chosen in one rig
/// names the same joint when passed back as rootJoint. Throws std::invalid_argument as
/// extractSkeleton does.
SkeletonRig selectRig(const CurveSkeleton& curve, const TriangleMesh& mesh, int targetNodes, int rootJoint);

} // namespace trimlab
