#include "ui/skeleton/skeleton_settings_store.h"

#include <QSettings>

#include <cmath>

namespace trimlab::ui {

namespace {

const QString kInitialWeight = QStringLiteral("skeleton/initialContractionWeight");
const QString kGrowth = QStringLiteral("skeleton/contractionGrowth");
const QString kMaxContraction = QStringLiteral("skeleton/maxContractionWeight");
const QString kMaxAttraction = QStringLiteral("skeleton/maxAttractionWeight");
const QString kIterations = QStringLiteral("skeleton/maxIterations");
const QString kOrdering = QStringLiteral("skeleton/ordering");
const QString kSolver = QStringLiteral("skeleton/solver");
const QString kDelta = QStringLiteral("skeleton/preCollapseFraction");
const QString kShape = QStringLiteral("skeleton/shapeWeight");
const QString kSampling = QStringLiteral("skeleton/samplingWeight");
const QString kRefine = QStringLiteral("skeleton/refine");
const QString kNodes = QStringLiteral("skeleton/nodes");
const QString kRoot = QStringLiteral("skeleton/root");
const QString kHeat = QStringLiteral("skeleton/heatConstant");
const QString kSkinning = QStringLiteral("skeleton/skinning");

double boundedReal(const QSettings& settings, const QString& key, double lo, double hi, double fallback)
{
    bool ok = false;
    const double value = settings.value(key).toDouble(&ok);
    return ok && std::isfinite(value) && value >= lo && value <= hi ? value : fallback;
}

int boundedInt(const QSettings& settings, const QString& key, int lo, int hi, int fallback)
{
    bool ok = false;
    const int value = settings.value(key).toInt(&ok);
    return ok && value >= lo && value <= hi ? value : fallback;
}

QString orderingName(SparseOrdering ordering)
{
    switch (ordering) {
    case SparseOrdering::Amd: return QStringLiteral("amd");
    case SparseOrdering::Colamd: return QStringLiteral("colamd");
    case SparseOrdering::Metis: break;
    }
    return QStringLiteral("metis");
}

SparseOrdering parseOrdering(const QString& name, SparseOrdering fallback)
{
    for (const SparseOrdering o : {SparseOrdering::Amd, SparseOrdering::Colamd, SparseOrdering::Metis})
        if (orderingName(o) == name)
            return o;
    return fallback;
}

} // namespace

SkeletonChoices loadSkeletonChoices(const QSettings& settings)
{
    const SkeletonChoices d;
    SkeletonChoices c;
    ContractionOptions& k = c.extraction.contraction;
    const ContractionOptions& dk = d.extraction.contraction;
    k.initialContractionWeight = boundedReal(settings, kInitialWeight, 0.0, 1e6, dk.initialContractionWeight);
    k.contractionGrowth = boundedReal(settings, kGrowth, 1.0, 100.0, dk.contractionGrowth);
    k.maxContractionWeight = boundedReal(settings, kMaxContraction, 1e-6, 1e9, dk.maxContractionWeight);
    k.maxAttractionWeight = boundedReal(settings, kMaxAttraction, 1e-6, 1e9, dk.maxAttractionWeight);
    k.maxIterations = boundedInt(settings, kIterations, 1, 200, dk.maxIterations);
    k.ordering = parseOrdering(settings.value(kOrdering).toString(), dk.ordering);
    const QString solver = settings.value(kSolver).toString();
    k.backend = solver == QStringLiteral("ldlt")      ? SparseBackend::EigenSimplicialLdlt
                : solver == QStringLiteral("cholmod") ? SparseBackend::Cholmod
                                                      : dk.backend;
    SimplificationOptions& s = c.extraction.simplification;
    s.preCollapseFraction = boundedReal(settings, kDelta, 0.0, 0.5, s.preCollapseFraction);
    s.shapeWeight = boundedReal(settings, kShape, 0.0, 1e6, s.shapeWeight);
    s.samplingWeight = boundedReal(settings, kSampling, 0.0, 1e6, s.samplingWeight);
    if (settings.contains(kRefine))
        c.extraction.refine = settings.value(kRefine).toBool();
    c.extraction.targetNodes = boundedInt(settings, kNodes, 20, 40, d.extraction.targetNodes);
    c.extraction.rootJoint = boundedInt(settings, kRoot, -1, 39, d.extraction.rootJoint);
    c.heatConstant = boundedReal(settings, kHeat, 1e-6, 1e6, d.heatConstant);
    const QString skinning = settings.value(kSkinning).toString();
    c.skinning = skinning == QStringLiteral("dqs")   ? SkinningMethod::Dqs
                 : skinning == QStringLiteral("lbs") ? SkinningMethod::Lbs
                                                     : d.skinning;
    return c;
}

void saveSkeletonChoices(QSettings& settings, const SkeletonChoices& c)
{
    const ContractionOptions& k = c.extraction.contraction;
    settings.setValue(kInitialWeight, k.initialContractionWeight);
    settings.setValue(kGrowth, k.contractionGrowth);
    settings.setValue(kMaxContraction, k.maxContractionWeight);
    settings.setValue(kMaxAttraction, k.maxAttractionWeight);
    settings.setValue(kIterations, k.maxIterations);
    settings.setValue(kOrdering, orderingName(k.ordering));
    settings.setValue(kSolver, k.backend == SparseBackend::EigenSimplicialLdlt ? QStringLiteral("ldlt")
                                                                               : QStringLiteral("cholmod"));
    settings.setValue(kDelta, c.extraction.simplification.preCollapseFraction);
    settings.setValue(kShape, c.extraction.simplification.shapeWeight);
    settings.setValue(kSampling, c.extraction.simplification.samplingWeight);
    settings.setValue(kRefine, c.extraction.refine);
    settings.setValue(kNodes, c.extraction.targetNodes);
    settings.setValue(kRoot, c.extraction.rootJoint);
    settings.setValue(kHeat, c.heatConstant);
    settings.setValue(kSkinning, c.skinning == SkinningMethod::Dqs ? QStringLiteral("dqs") : QStringLiteral("lbs"));
}

} // namespace trimlab::ui
