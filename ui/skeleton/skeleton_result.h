#pragma once
/// \file
/// One run of the Skeleton panel (skeleton_panel.h) and the jobs that make it, on a worker
/// thread: the full pipeline — extractSkeleton (stages A–D) then the bone-heat weights
/// (stage E) — as the `trimlab skeleton` verb chains it, or, when only the node count or
/// the root changed, selectRig on the kept curve skeleton plus new weights (no new
/// contraction). Immutable once made; the panel shares it with the overlay and the views.

#include "ui/skeleton/skeleton_choices.h"

#include "core/util/task_control.h"
#include "core/mesh/triangle_mesh.h"
#include "core/skeleton/bone_heat_weights.h"
#include "core/skeleton/skeleton_evaluation.h"
#include "core/skeleton/skeleton_extraction.h"

#include <memory>

namespace trimlab::ui {

/// Which stages the last run executed (a rig-only run keeps stages A–C of the one before).
enum class SkeletonRunKind { Full, RigOnly };

struct SkeletonResult {
    /// Stages A–C (and the first selection); shared with rig-only re-runs.
    std::shared_ptr<const SkeletonExtraction> extraction;
    SkeletonRig rig; ///< the rig in use (extraction->rig, or selectRig's)
    std::shared_ptr<const BoneHeatSolver> weights;
    SkeletonRunKind kind = SkeletonRunKind::Full;
    SkeletonChoices choices; ///< what it was made with
    /// Milliseconds of this run's stages; contraction, simplification and refinement are 0
    /// in a rig-only run (they did not run).
    SkeletonStageTimes times;
    double weightsMs = 0.0;
    /// The evaluator's numbers (skeleton_evaluation.h) for the curve skeleton and the rig
    /// in use; a rig-only run keeps the curve's.
    SkeletonEvaluation curveQuality;
    SkeletonEvaluation rigQuality;

    [[nodiscard]] double totalMs() const
    {
        return times.contractionMs + times.simplificationMs + times.refinementMs + times.selectionMs + weightsMs;
    }
};

/// The full pipeline on `mesh` (object space), then the evaluation of its curve and rig
/// (stage "evaluation"). Throws what extractSkeleton and
/// BoneHeatSolver throw (SkeletonInputError for a refused mesh, OperationCancelled).
[[nodiscard]] std::shared_ptr<const SkeletonResult> runSkeletonPipeline(const TriangleMesh& mesh,
                                                                        const SkeletonChoices& choices,
                                                                        const TaskControl& control);

/// selectRig on `previous`'s curve skeleton with the node count and root of `choices`,
/// then new weights and the rig's evaluation. Reports stages "selection", the weights' own
/// and "evaluation".
[[nodiscard]] std::shared_ptr<const SkeletonResult> rerunSkeletonRig(const TriangleMesh& mesh,
                                                                     const SkeletonResult& previous,
                                                                     const SkeletonChoices& choices,
                                                                     const TaskControl& control);

} // namespace trimlab::ui
