#pragma once
/// \file
/// What the Segmentation panel lets the user choose, as one value (persisted by
/// animation_settings_store.h): the per-pose feature and its reference pose, the
/// clustering method and clusters per pose, worker threads, the cleaning strength h,
/// the mode and whether the animation is colored by segment.

#include "core/animation/animation_segmenter.h"
#include "core/animation/segmentation_parameters.h"

namespace trimlab::ui {

using trimlab::SegmentationMode;

/// Ranges and defaults are the rows of core/animation/segmentation_parameters.h.
struct SegmentationChoices {
    FeatureKind feature = FeatureKind(segmentation_parameters::kFeature.defaultValue);
    ReferenceMode reference = ReferenceMode(segmentation_parameters::kReference.defaultValue);
    PartitionMethod method = PartitionMethod(segmentation_parameters::kMethod.defaultValue);
    int clusters = int(segmentation_parameters::kClusters.defaultValue);
    int threads = int(segmentation_parameters::kThreads.defaultValue); ///< 0 = every core
    double h = segmentation_parameters::kH.defaultValue;
    SegmentationMode mode = SegmentationMode(segmentation_parameters::kMode.defaultValue);
    bool colorBySegment = segmentation_parameters::kColorBySegment.defaultValue != 0.0;

    /// The core settings these choices ask for.
    [[nodiscard]] SegmenterSettings segmenterSettings() const
    {
        SegmenterSettings settings;
        settings.feature.kind = feature;
        settings.feature.reference = reference;
        settings.partition.method = method;
        settings.partition.clusters = std::size_t(clusters);
        settings.threads = unsigned(threads);
        return settings;
    }

    friend bool operator==(const SegmentationChoices&, const SegmentationChoices&) = default;
};

} // namespace trimlab::ui
