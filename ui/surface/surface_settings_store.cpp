#include "ui/surface/surface_settings_store.h"

#include "ui/common/parameter_settings.h"

#include <QSettings>

namespace trimlab::ui {

namespace {

const QString kSegmentsU = QStringLiteral("surface/segmentsU");
const QString kSegmentsV = QStringLiteral("surface/segmentsV");
const QString kPatchDegree = QStringLiteral("surface/patchDegree");
const QString kScheme = QStringLiteral("surface/scheme");
const QString kLevel = QStringLiteral("surface/level");
const QString kMode = QStringLiteral("surface/mode");
const QString kShowNet = QStringLiteral("surface/showNet");
const QString kNormalStep = QStringLiteral("surface/normalStepFraction");

} // namespace

SurfaceChoices loadSurfaceChoices(const QSettings& settings)
{
    const SurfaceChoices fallback;
    SurfaceChoices choices;
    choices.segmentsU = readBoundedInteger(settings, kSegmentsU, SurfaceChoices::kMinSegments,
                                           SurfaceChoices::kMaxSegments, fallback.segmentsU);
    choices.segmentsV = readBoundedInteger(settings, kSegmentsV, SurfaceChoices::kMinSegments,
                                           SurfaceChoices::kMaxSegments, fallback.segmentsV);
    choices.patchDegree =
        readBoundedInteger(settings, kPatchDegree, 1, SurfaceChoices::kMaxPatchDegree, fallback.patchDegree);
    const QString scheme = settings.value(kScheme).toString();
    choices.scheme = scheme == QLatin1String("loop")            ? SubdivisionScheme::Loop
                     : scheme == QLatin1String("catmull-clark") ? SubdivisionScheme::CatmullClark
                                                                : fallback.scheme;
    choices.level = readBoundedInteger(settings, kLevel, 0, SubdivisionSurface::kMaxLevel, fallback.level);
    const QString mode = settings.value(kMode).toString();
    choices.mode = mode == QLatin1String("uniform") ? SubdivisionMode::Uniform
                   : mode == QLatin1String("limit") ? SubdivisionMode::Limit
                                                    : fallback.mode;
    choices.showNet = settings.value(kShowNet, fallback.showNet).toBool();
    const double step = readBoundedNumber(settings, kNormalStep, 0.0, SurfaceChoices::kMaxNormalStepFraction,
                                          fallback.normalStepFraction);
    choices.normalStepFraction = step > 0.0 ? step : fallback.normalStepFraction;
    return choices;
}

void saveSurfaceChoices(QSettings& settings, const SurfaceChoices& choices)
{
    settings.setValue(kSegmentsU, choices.segmentsU);
    settings.setValue(kSegmentsV, choices.segmentsV);
    settings.setValue(kPatchDegree, choices.patchDegree);
    settings.setValue(kScheme, choices.scheme == SubdivisionScheme::Loop ? QStringLiteral("loop")
                                                                         : QStringLiteral("catmull-clark"));
    settings.setValue(kLevel, choices.level);
    settings.setValue(kMode,
                      choices.mode == SubdivisionMode::Uniform ? QStringLiteral("uniform") : QStringLiteral("limit"));
    settings.setValue(kShowNet, choices.showNet);
    settings.setValue(kNormalStep, choices.normalStepFraction);
}

} // namespace trimlab::ui
