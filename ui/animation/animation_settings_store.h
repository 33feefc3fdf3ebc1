#pragma once
/// \file
/// Reading and writing the Segmentation panel's choices (keys "segmentation/…": feature,
/// reference and method by their command-line names, clusters, threads, h, mode,
/// colorBySegment), the Timeline's playback (keys "timeline/fps", "timeline/loop") and
/// pose classification ("timeline/poseRule": "static" or a dynamic rule's command-line
/// name, "timeline/poseReference": "rest" or "previous") in a QSettings. Missing or unusable values fall back to the defaults of
/// SegmentationChoices and TimelinePanel, field by field.

#include "ui/animation/pose_history_choices.h"
#include "ui/animation/segmentation_choices.h"

class QSettings;

namespace trimlab::ui {

[[nodiscard]] SegmentationChoices loadSegmentationChoices(const QSettings& settings);
void saveSegmentationChoices(QSettings& settings, const SegmentationChoices& choices);

struct PlaybackChoices {
    int fps = 24;
    bool loop = true;
};

[[nodiscard]] PlaybackChoices loadPlaybackChoices(const QSettings& settings);
void savePlaybackChoices(QSettings& settings, const PlaybackChoices& choices);

[[nodiscard]] PoseHistoryChoices loadPoseHistoryChoices(const QSettings& settings);
void savePoseHistoryChoices(QSettings& settings, const PoseHistoryChoices& choices);

} // namespace trimlab::ui
