#include "ui/animation/animation_settings_store.h"

#include "ui/animation/timeline_panel.h"
#include "ui/common/parameter_settings.h"

#include <QSettings>

#include <optional>

namespace trimlab::ui {

namespace {

const QString kFps = QStringLiteral("timeline/fps");
const QString kLoop = QStringLiteral("timeline/loop");
const QString kPoseRule = QStringLiteral("timeline/poseRule");
const QString kPoseReference = QStringLiteral("timeline/poseReference");
const QString kStaticPoseRule = QStringLiteral("static");

QString text(std::string_view name)
{
    return QString::fromLatin1(name.data(), qsizetype(name.size()));
}

} // namespace

SegmentationChoices loadSegmentationChoices(const QSettings& settings)
{
    using namespace segmentation_parameters;
    SegmentationChoices choices;
    choices.feature = readParameterAs<FeatureKind>(settings, kFeature);
    choices.reference = readParameterAs<ReferenceMode>(settings, kReference);
    choices.method = readParameterAs<PartitionMethod>(settings, kMethod);
    choices.clusters = readParameterAs<int>(settings, kClusters);
    choices.threads = readParameterAs<int>(settings, kThreads);
    choices.h = readParameter(settings, kH);
    choices.mode = readParameterAs<SegmentationMode>(settings, kMode);
    choices.colorBySegment = readParameterAs<bool>(settings, kColorBySegment);
    return choices;
}

void saveSegmentationChoices(QSettings& settings, const SegmentationChoices& choices)
{
    using namespace segmentation_parameters;
    writeParameterFrom(settings, kFeature, choices.feature);
    writeParameterFrom(settings, kReference, choices.reference);
    writeParameterFrom(settings, kMethod, choices.method);
    writeParameter(settings, kClusters, choices.clusters);
    writeParameter(settings, kThreads, choices.threads);
    writeParameter(settings, kH, choices.h);
    writeParameterFrom(settings, kMode, choices.mode);
    writeParameterFrom(settings, kColorBySegment, choices.colorBySegment);
}

PlaybackChoices loadPlaybackChoices(const QSettings& settings)
{
    const PlaybackChoices defaults;
    PlaybackChoices choices;
    choices.fps = readBoundedInteger(settings, kFps, TimelinePanel::kMinFps, TimelinePanel::kMaxFps, defaults.fps);
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
