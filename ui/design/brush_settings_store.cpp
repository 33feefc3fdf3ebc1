#include "ui/design/brush_settings_store.h"

#include <QSettings>

#include <cmath>
#include <string>

namespace trimlab::ui {

namespace {

const QString kRadiusFraction = QStringLiteral("brush/radiusFraction");
const QString kStrength = QStringLiteral("brush/strength");
const QString kProfile = QStringLiteral("brush/profile");
const QString kIterations = QStringLiteral("brush/smoothingIterations");
const QString kWeights = QStringLiteral("brush/smoothingWeights");
const QString kStep = QStringLiteral("brush/smoothingStep");
const QString kEnabled = QStringLiteral("brush/toolEnabled");

/// The stored number at `key` when finite and in [lo, hi], else `fallback`.
double boundedDouble(const QSettings& settings, const QString& key, double lo, double hi, double fallback)
{
    bool ok = false;
    const double value = settings.value(key).toDouble(&ok);
    return ok && std::isfinite(value) && value >= lo && value <= hi ? value : fallback;
}

QString latin1(std::string_view text)
{
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}

} // namespace

BrushChoices loadBrushChoices(const QSettings& settings)
{
    const BrushChoices fallback;
    BrushChoices choices;
    choices.radiusFraction = boundedDouble(settings, kRadiusFraction, BrushChoices::kMinRadiusFraction,
                                           BrushChoices::kMaxRadiusFraction, fallback.radiusFraction);
    deform::BrushSettings& brush = choices.settings;
    brush.strength = boundedDouble(settings, kStrength, -BrushChoices::kMaxStrength, BrushChoices::kMaxStrength,
                                   fallback.settings.strength);
    brush.profile = deform::parseFalloffProfile(settings.value(kProfile).toString().toStdString())
                        .value_or(fallback.settings.profile);
    brush.smoothingIterations = int(boundedDouble(settings, kIterations, 0, BrushChoices::kMaxIterations,
                                                  fallback.settings.smoothingIterations));
    brush.smoothingWeights = deform::parseSmoothingWeights(settings.value(kWeights).toString().toStdString())
                                 .value_or(fallback.settings.smoothingWeights);
    brush.smoothingStep = boundedDouble(settings, kStep, 0.01, 1.0, fallback.settings.smoothingStep);
    choices.toolEnabled = settings.value(kEnabled, fallback.toolEnabled).toBool();
    return choices;
}

void saveBrushChoices(QSettings& settings, const BrushChoices& choices)
{
    settings.setValue(kRadiusFraction, choices.radiusFraction);
    settings.setValue(kStrength, choices.settings.strength);
    settings.setValue(kProfile, latin1(deform::falloffProfileName(choices.settings.profile)));
    settings.setValue(kIterations, choices.settings.smoothingIterations);
    settings.setValue(kWeights, latin1(deform::smoothingWeightsName(choices.settings.smoothingWeights)));
    settings.setValue(kStep, choices.settings.smoothingStep);
    settings.setValue(kEnabled, choices.toolEnabled);
}

} // namespace trimlab::ui
