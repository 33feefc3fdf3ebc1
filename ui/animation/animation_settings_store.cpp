#include "ui/animation/animation_settings_store.h"

#include "ui/animation/timeline_panel.h"

#include <QSettings>

#include <array>
#include <cmath>
#include <optional>

namespace trimlab::ui {

namespace {

const QString kFeature = QStringLiteral("segmentation/feature");
const QString kReference = QStringLiteral("segmentation/reference");
const QString kMethod = QStringLiteral("segmentation/method");
const QString kClusters = QStringLiteral("segmentation/clusters");
const QString kThreads = QStringLiteral("segmentation/threads");
const QString kH = QStringLiteral("segmentation/h");
const QString kMode = QStringLiteral("segmentation/mode");
const QString kColorBySegment = QStringLiteral("segmentation/colorBySegment");
const QString kFps = QStringLiteral("timeline/fps");
const QString kLoop = QStringLiteral("timeline/loop");
const QString kPoseRule = QStringLiteral("timeline/poseRule");
const QString kPoseReference = QStringLiteral("timeline/poseReference");
const QString kStaticPoseRule = QStringLiteral("static");

constexpr std::array kModeNames{"global", "real-time", "variable"};

QString text(std::string_view name)
{
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

std::optional<FeatureKind> parseFeature(const QString& name)
{
    for (const FeatureKind kind : {FeatureKind::RotationAngle, FeatureKind::Velocity, FeatureKind::Acceleration})
        if (text(featureName(kind)) == name)
            return kind;
    return std::nullopt;
}

std::optional<ReferenceMode> parseReference(const QString& name)
{
    for (const ReferenceMode mode : {ReferenceMode::Rest, ReferenceMode::Previous})
        if (text(referenceName(mode)) == name)
            return mode;
    return std::nullopt;
}

std::optional<SegmentationMode> parseMode(const QString& name)
{
    for (std::size_t i = 0; i < kModeNames.size(); ++i)
        if (name == QLatin1String(kModeNames[i]))
            return SegmentationMode(i);
    return std::nullopt;
}

int boundedInt(const QSettings& settings, const QString& key, int lo, int hi, int fallback)
{
    bool ok = false;
    const int value = settings.value(key).toInt(&ok);
    return ok && value >= lo && value <= hi ? value : fallback;
}

double boundedReal(const QSettings& settings, const QString& key, double lo, double hi, double fallback)
{
    bool ok = false;
    const double value = settings.value(key).toDouble(&ok);
    return ok && std::isfinite(value) && value >= lo && value <= hi ? value : fallback;
}

} // namespace

SegmentationChoices loadSegmentationChoices(const QSettings& settings)
{
    const SegmentationChoices defaults;
    SegmentationChoices choices;
    choices.feature = parseFeature(settings.value(kFeature).toString()).value_or(defaults.feature);
    choices.reference = parseReference(settings.value(kReference).toString()).value_or(defaults.reference);
    choices.method =
        parsePartitionMethod(settings.value(kMethod).toString().toStdString()).value_or(defaults.method);
    choices.clusters = boundedInt(settings, kClusters, 1, SegmentationChoices::kMaxClusters, defaults.clusters);
    choices.threads = boundedInt(settings, kThreads, 0, SegmentationChoices::kMaxThreads, defaults.threads);
    choices.h = boundedReal(settings, kH, 0.0, 1.0, defaults.h);
    choices.mode = parseMode(settings.value(kMode).toString()).value_or(defaults.mode);
    choices.colorBySegment = settings.value(kColorBySegment, defaults.colorBySegment).toBool();
    return choices;
}

void saveSegmentationChoices(QSettings& settings, const SegmentationChoices& choices)
{
    settings.setValue(kFeature, text(featureName(choices.feature)));
    settings.setValue(kReference, text(referenceName(choices.reference)));
    settings.setValue(kMethod, text(partitionMethodName(choices.method)));
    settings.setValue(kClusters, choices.clusters);
    settings.setValue(kThreads, choices.threads);
    settings.setValue(kH, choices.h);
    settings.setValue(kMode, QLatin1String(kModeNames[std::size_t(choices.mode)]));
    settings.setValue(kColorBySegment, choices.colorBySegment);
}

PlaybackChoices loadPlaybackChoices(const QSettings& settings)
{
    const PlaybackChoices defaults;
    PlaybackChoices choices;
    choices.fps = boundedInt(settings, kFps, TimelinePanel::kMinFps, TimelinePanel::kMaxFps, defaults.fps);
    choices.loop = settings.value(kLoop, defaults.loop).toBool();
    return choices;
}

void savePlaybackChoices(QSettings& settings, const PlaybackChoices& choices)
{
    settings.setValue(kFps, choices.fps);
    settings.setValue(kLoop, choices.loop);
}

PoseHistoryChoices loadPoseHistoryChoices(const QSettings& settings)
{
    const PoseHistoryChoices defaults;
    PoseHistoryChoices choices;
    choices.rule = parseDynamicRule(settings.value(kPoseRule).toString().toStdString()); // "static" or unknown: none
    choices.reference =
        parsePoseReference(settings.value(kPoseReference).toString().toStdString()).value_or(defaults.reference);
    return choices;
}

void savePoseHistoryChoices(QSettings& settings, const PoseHistoryChoices& choices)
{
    settings.setValue(kPoseRule, choices.rule ? text(dynamicRuleName(*choices.rule)) : kStaticPoseRule);
    settings.setValue(kPoseReference, text(poseReferenceName(choices.reference)));
}

} // namespace trimlab::ui
