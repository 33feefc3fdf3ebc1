#include "ui/skeleton/skeleton_result.h"

#include <QElapsedTimer>

namespace trimlab::ui {

namespace {

BoneHeatOptions heatOptions(const SkeletonChoices& choices)
{
    BoneHeatOptions options;
    options.terms.heatConstant = choices.heatConstant;
    options.backend = choices.extraction.contraction.backend;
    options.ordering = choices.extraction.contraction.ordering;
    return options;
}

// Stage E, timed; its own progress stages are "visibility" and "weights".
void computeWeights(const TriangleMesh& mesh, SkeletonResult& result, const TaskControl& control)
{
    QElapsedTimer timer;
    timer.start();
    result.weights = std::make_shared<const BoneHeatSolver>(mesh, result.rig, heatOptions(result.choices), control);
    result.weightsMs = double(timer.nsecsElapsed()) * 1e-6;
}

} // namespace

bool SkeletonChoices::needsContraction(const SkeletonChoices& other) const
{
    const ContractionOptions& a = extraction.contraction;
    const ContractionOptions& b = other.extraction.contraction;
    const SimplificationOptions& s = extraction.simplification;
    const SimplificationOptions& t = other.extraction.simplification;
    return a.initialContractionWeight != b.initialContractionWeight ||
           a.initialAttractionWeight != b.initialAttractionWeight || a.contractionGrowth != b.contractionGrowth ||
           a.maxContractionWeight != b.maxContractionWeight || a.maxAttractionWeight != b.maxAttractionWeight ||
           a.minAngleDegrees != b.minAngleDegrees || a.minAreaRatio != b.minAreaRatio ||
           a.minAreaDecrease != b.minAreaDecrease || a.ordering != b.ordering || a.backend != b.backend ||
           a.maxIterations != b.maxIterations || a.collapseFraction != b.collapseFraction ||
           a.inputCollapseFraction != b.inputCollapseFraction ||
           s.preCollapseFraction != t.preCollapseFraction ||
           s.shapeWeight != t.shapeWeight || s.samplingWeight != t.samplingWeight ||
           extraction.refine != other.extraction.refine ||
           extraction.resampleFraction != other.extraction.resampleFraction ||
           extraction.centre != other.extraction.centre;
}

std::shared_ptr<const SkeletonResult> runSkeletonPipeline(const TriangleMesh& mesh, const SkeletonChoices& choices,
                                                          const TaskControl& control)
{
    auto result = std::make_shared<SkeletonResult>();
    result->choices = choices;
    auto extraction = std::make_shared<SkeletonExtraction>(extractSkeleton(mesh, choices.extraction, control));
    result->rig = extraction->rig;
    result->times = extraction->times;
    result->extraction = std::move(extraction);
    computeWeights(mesh, *result, control);
    control.report("evaluation", 0, 1);
    const SkeletonEvaluator evaluator(mesh);
    result->curveQuality = evaluator.evaluate(skeletonGraph(result->extraction->curve));
    result->rigQuality = evaluator.evaluate(skeletonGraph(result->rig));
    control.report("evaluation", 1, 1);
    return result;
}

std::shared_ptr<const SkeletonResult> rerunSkeletonRig(const TriangleMesh& mesh, const SkeletonResult& previous,
                                                       const SkeletonChoices& choices, const TaskControl& control)
{
    auto result = std::make_shared<SkeletonResult>();
    result->choices = choices;
    result->kind = SkeletonRunKind::RigOnly;
    result->extraction = previous.extraction;
    control.report("selection", 0, 1);
    QElapsedTimer timer;
    timer.start();
    result->rig = selectRig(previous.extraction->curve, mesh, choices.extraction.targetNodes,
                            choices.extraction.rootJoint);
    result->times.selectionMs = double(timer.nsecsElapsed()) * 1e-6;
    control.report("selection", 1, 1);
    control.throwIfCancelled();
    computeWeights(mesh, *result, control);
    control.report("evaluation", 0, 1);
    result->curveQuality = previous.curveQuality;
    result->rigQuality = SkeletonEvaluator(mesh).evaluate(skeletonGraph(result->rig));
    control.report("evaluation", 1, 1);
    return result;
}

} // namespace trimlab::ui
