#pragma once
/// \file
/// The whole skeleton operation, as both `trimlab skeleton` and the Skeleton panel run it:
/// extraction by mesh contraction (stages A–D, skeleton_extraction.h), the bone-heat
/// weights of the rig (stage E, bone_heat_weights.h) and the evaluation of the curve
/// skeleton and the rig (skeleton_evaluation.h). One function composes the stages, so the
/// command line and the panel cannot drift apart in what they compute or with which
/// settings (the heat constant, the factorization of the weights).
///
/// The rig-only re-run serves a change of the node count, the root or the heat constant:
/// selectRig on the curve skeleton of an earlier run, new weights and the rig's evaluation,
/// no new contraction.

#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/rig_measures.h"
#include "core/skeleton/skeleton_evaluation.h"
#include "core/skeleton/skeleton_extraction.h"
#include "core/util/task_control.h"

#include <memory>

namespace trimlab {

/// Everything the pipeline is run with.
struct SkeletonPipelineOptions {
    /// Stages A–D (targetNodes, rootJoint, the contraction's factorization, ...).
    SkeletonOptions extraction;
    /// c of H_jj = c/d² (bone_heat_terms.h); Pinocchio's 1.
    double heatConstant = 1.0;
};

/// Which stages a run executed (a rig-only run keeps stages A–C of an earlier one).
enum class SkeletonRunKind { Full, RigOnly };

/// One run's results; immutable once made, so that callers may share it.
struct SkeletonResult {
    /// Stages A–C and the first selection; shared with the rig-only re-runs made from it.
    std::shared_ptr<const SkeletonExtraction> extraction;
    SkeletonRig rig; ///< the rig in use (extraction->rig, or selectRig's)
    std::shared_ptr<const BoneHeatSolver> weights;
    SkeletonRunKind kind = SkeletonRunKind::Full;
    SkeletonPipelineOptions options; ///< what it was made with
    /// Milliseconds of this run's stages; contraction, simplification and refinement are 0
    /// in a rig-only run (they did not run).
    SkeletonStageTimes times;
    double weightsMs = 0.0;
    double evaluationMs = 0.0;
    /// The evaluator's numbers for the curve skeleton and the rig in use; a rig-only run
    /// keeps the curve's.
    SkeletonEvaluation curveQuality;
    SkeletonEvaluation rigQuality;
    /// The rig's joints, root, turn-backs and weight leakage (rig_measures.h).
    RigMeasures rigMeasures;

    /// Stages A–E (the evaluation is not part of the paper's Table III).
    [[nodiscard]] double totalMs() const
    {
        return times.contractionMs + times.simplificationMs + times.refinementMs + times.selectionMs + weightsMs;
    }
};

/// The bone-heat settings of a run: the heat constant, and the factorization the
/// contraction uses.
[[nodiscard]] BoneHeatOptions boneHeatOptions(const SkeletonPipelineOptions& options);

/// Stages A–E on `mesh` (object or world space: the skeleton lives in the mesh's space),
/// then the evaluation of the curve and the rig. Progress stages: extractSkeleton's, the
/// weights' ("visibility", "weights"), then "evaluation". Throws what extractSkeleton and
/// BoneHeatSolver throw (SkeletonInputError for a refused mesh, std::invalid_argument for
/// options out of range, OperationCancelled).
[[nodiscard]] SkeletonResult runSkeletonPipeline(const TriangleMesh& mesh, const SkeletonPipelineOptions& options,
                                                 const TaskControl& control = {});

/// selectRig on `previous`'s curve skeleton (previous was made from `mesh`) with the node
/// count and root of `options`, then new weights with its heat constant and the rig's
/// evaluation. Progress stages "selection", the weights' and "evaluation". Throws as
/// runSkeletonPipeline.
[[nodiscard]] SkeletonResult rerunSkeletonRig(const TriangleMesh& mesh, const SkeletonResult& previous,
                                              const SkeletonPipelineOptions& options, const TaskControl& control = {});

} // namespace trimlab
