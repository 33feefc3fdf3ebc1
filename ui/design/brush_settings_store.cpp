#include "ui/design/brush_settings_store.h"

#include "ui/common/parameter_settings.h"

#include <QSettings>

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

QString latin1(std::string_view text)
{
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}

} // namespace

BrushChoices loadBrushChoices(const QSettings& settings)
{
    const BrushChoices fallback;
    BrushChoices choices;
    choices.radiusFraction = readBoundedNumber(settings, kRadiusFraction, BrushChoices::kMinRadiusFraction,
                                               BrushChoices::kMaxRadiusFraction, fallback.radiusFraction);
    deform::BrushSettings& brush = choices.settings;
    brush.strength = readBoundedNumber(settings, kStrength, -BrushChoices::kMaxStrength, BrushChoices::kMaxStrength,
                                       fallback.settings.strength);
    brush.profile = deform::parseFalloffProfile(settings.value(kProfile).toString().toStdString())
                        .value_or(fallback.settings.profile);
    brush.smoothingIterations = readBoundedInteger(settings, kIterations, 0, BrushChoices::kMaxIterations,
                                                   fallback.settings.smoothingIterations);
    brush.smoothingWeights = deform::parseSmoothingWeights(settings.value(kWeights).toString().toStdString())
                                 .value_or(fallback.settings.smoothingWeights);
    brush.smoothingStep = readBoundedNumber(settings, kStep, 0.01, 1.0, fallback.settings.smoothingStep);
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
