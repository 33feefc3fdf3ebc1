#pragma once
/// \file
/// Reading and writing the Segmentation panel's choices (keys "segmentation/…": feature,
/// reference and method by their command-line names, clusters, threads, h, mode,
/// colorBySegment) and the Timeline's playback (keys "timeline/fps", "timeline/loop") in
/// a QSettings. Missing or unusable values fall back to the defaults of
/// SegmentationChoices and TimelinePanel, field by field.

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

} // namespace trimlab::ui
