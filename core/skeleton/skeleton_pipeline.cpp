#include "core/skeleton/skeleton_pipeline.h"

#include <chrono>

namespace trimlab {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Stage E, timed; its own progress stages are "visibility" and "weights".
void computeWeights(const TriangleMesh& mesh, SkeletonResult& result, const TaskControl& control)
{
    const Clock::time_point start = Clock::now();
    result.weights = std::make_shared<const BoneHeatSolver>(mesh, result.rig, boneHeatOptions(result.options), control);
    result.weightsMs = millisecondsSince(start);
}

// The rig's evaluation, and the curve's when `curve` is set.
void evaluate(const TriangleMesh& mesh, SkeletonResult& result, bool curve, const TaskControl& control)
{
    control.report("evaluation", 0, 1);
    const Clock::time_point start = Clock::now();
    const SkeletonEvaluator evaluator(mesh);
    if (curve)
        result.curveQuality = evaluator.evaluate(skeletonGraph(result.extraction->curve));
    result.rigQuality = evaluator.evaluate(skeletonGraph(result.rig));
    result.rigMeasures = measureRig(result.rig, result.weights->weights());
    result.evaluationMs = millisecondsSince(start);
    control.report("evaluation", 1, 1);
}

} // namespace

BoneHeatOptions boneHeatOptions(const SkeletonPipelineOptions& options)
{
    BoneHeatOptions heat;
    heat.terms.heatConstant = options.heatConstant;
    heat.backend = options.extraction.contraction.backend;
    heat.ordering = options.extraction.contraction.ordering;
    return heat;
}

SkeletonResult runSkeletonPipeline(const TriangleMesh& mesh, const SkeletonPipelineOptions& options,
                                   const TaskControl& control)
{
    SkeletonResult result;
    result.options = options;
    auto extraction = std::make_shared<const SkeletonExtraction>(extractSkeleton(mesh, options.extraction, control));
    result.rig = extraction->rig;
    result.times = extraction->times;
    result.extraction = std::move(extraction);
    computeWeights(mesh, result, control);
    evaluate(mesh, result, true, control);
    return result;
}

SkeletonResult rerunSkeletonRig(const TriangleMesh& mesh, const SkeletonResult& previous,
                                const SkeletonPipelineOptions& options, const TaskControl& control)
{
    SkeletonResult result;
    result.options = options;
    result.kind = SkeletonRunKind::RigOnly;
    result.extraction = previous.extraction;
    control.report("selection", 0, 1);
    const Clock::time_point start = Clock::now();
    result.rig =
        selectRig(previous.extraction->curve, mesh, options.extraction.targetNodes, options.extraction.rootJoint);
    result.times.selectionMs = millisecondsSince(start);
    control.report("selection", 1, 1);
    control.throwIfCancelled();
    computeWeights(mesh, result, control);
    result.curveQuality = previous.curveQuality;
    evaluate(mesh, result, false, control);
    return result;
}

} // namespace trimlab
