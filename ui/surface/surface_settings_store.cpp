#include "ui/surface/surface_settings_store.h"

#include <QSettings>

#include <cmath>

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

/// The stored integer at `key` when it is one and in [lo, hi], else `fallback`.
int boundedInt(const QSettings& settings, const QString& key, int lo, int hi, int fallback)
{
    bool ok = false;
    const int value = settings.value(key).toInt(&ok);
    return ok && value >= lo && value <= hi ? value : fallback;
}

} // namespace

SurfaceChoices loadSurfaceChoices(const QSettings& settings)
{
    const SurfaceChoices fallback;
    SurfaceChoices choices;
    choices.segmentsU = boundedInt(settings, kSegmentsU, SurfaceChoices::kMinSegments, SurfaceChoices::kMaxSegments,
                                   fallback.segmentsU);
    choices.segmentsV = boundedInt(settings, kSegmentsV, SurfaceChoices::kMinSegments, SurfaceChoices::kMaxSegments,
                                   fallback.segmentsV);
    choices.patchDegree = boundedInt(settings, kPatchDegree, 1, SurfaceChoices::kMaxPatchDegree, fallback.patchDegree);
    const QString scheme = settings.value(kScheme).toString();
    choices.scheme = scheme == QLatin1String("loop")            ? SubdivisionScheme::Loop
                     : scheme == QLatin1String("catmull-clark") ? SubdivisionScheme::CatmullClark
                                                                : fallback.scheme;
    choices.level = boundedInt(settings, kLevel, 0, SubdivisionSurface::kMaxLevel, fallback.level);
    const QString mode = settings.value(kMode).toString();
    choices.mode = mode == QLatin1String("uniform") ? SubdivisionMode::Uniform
                   : mode == QLatin1String("limit") ? SubdivisionMode::Limit
                                                    : fallback.mode;
    choices.showNet = settings.value(kShowNet, fallback.showNet).toBool();
    bool ok = false;
    const double step = settings.value(kNormalStep).toDouble(&ok);
    choices.normalStepFraction = ok && std::isfinite(step) && step > 0.0 && step <= SurfaceChoices::kMaxNormalStepFraction
                                     ? step
                                     : fallback.normalStepFraction;
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
    settings.setValue(kMode, choices.mode == SubdivisionMode::Uniform ? QStringLiteral("uniform")
                                                                      : QStringLiteral("limit"));
    settings.setValue(kShowNet, choices.showNet);
    settings.setValue(kNormalStep, choices.normalStepFraction);
}

} // namespace trimlab::ui
