#include "ui/skeleton/skeleton_settings_store.h"

#include "ui/common/parameter_settings.h"

#include <QSettings>

namespace trimlab::ui {

SkeletonChoices loadSkeletonChoices(const QSettings& settings)
{
    using namespace skeleton_parameters;
    SkeletonChoices c;
    ContractionOptions& k = c.extraction.contraction;
    k.initialContractionWeight = readParameter(settings, kInitialContractionWeight);
    k.contractionGrowth = readParameter(settings, kContractionGrowth);
    k.maxContractionWeight = readParameter(settings, kMaxContractionWeight);
    k.maxAttractionWeight = readParameter(settings, kMaxAttractionWeight);
    k.maxIterations = readParameterAs<int>(settings, kMaxIterations);
    k.ordering = readParameterAs<SparseOrdering>(settings, kOrdering);
    k.backend = readParameterAs<SparseBackend>(settings, kSolver);
    SimplificationOptions& s = c.extraction.simplification;
    s.preCollapseFraction = readParameter(settings, kPreCollapseFraction);
    s.shapeWeight = readParameter(settings, kShapeWeight);
    s.samplingWeight = readParameter(settings, kSamplingWeight);
    c.extraction.refine = readParameterAs<bool>(settings, kRefine);
    c.extraction.targetNodes = readParameterAs<int>(settings, kTargetNodes);
    c.extraction.rootJoint = readParameterAs<int>(settings, kRootJoint);
    c.heatConstant = readParameter(settings, kHeatConstant);
    c.skinning = readParameterAs<SkinningMethod>(settings, kPoseSkinning);
    return c;
}

void saveSkeletonChoices(QSettings& settings, const SkeletonChoices& c)
{
    using namespace skeleton_parameters;
    const ContractionOptions& k = c.extraction.contraction;
    writeParameter(settings, kInitialContractionWeight, k.initialContractionWeight);
    writeParameter(settings, kContractionGrowth, k.contractionGrowth);
    writeParameter(settings, kMaxContractionWeight, k.maxContractionWeight);
    writeParameter(settings, kMaxAttractionWeight, k.maxAttractionWeight);
    writeParameter(settings, kMaxIterations, k.maxIterations);
    writeParameterFrom(settings, kOrdering, k.ordering);
    writeParameterFrom(settings, kSolver, k.backend);
    const SimplificationOptions& s = c.extraction.simplification;
    writeParameter(settings, kPreCollapseFraction, s.preCollapseFraction);
    writeParameter(settings, kShapeWeight, s.shapeWeight);
    writeParameter(settings, kSamplingWeight, s.samplingWeight);
    writeParameterFrom(settings, kRefine, c.extraction.refine);
    writeParameter(settings, kTargetNodes, c.extraction.targetNodes);
    writeParameter(settings, kRootJoint, c.extraction.rootJoint);
    writeParameter(settings, kHeatConstant, c.heatConstant);
    writeParameterFrom(settings, kPoseSkinning, c.skinning);
}

} // namespace trimlab::ui
