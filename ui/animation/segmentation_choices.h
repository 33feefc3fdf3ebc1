#pragma once
/// \file
/// What the Segmentation panel lets the user choose, as one value (persisted by
/// animation_settings_store.h): the per-pose feature and its reference pose, the
/// clustering method and clusters per pose, worker threads, the cleaning strength h,
/// the mode and whether the animation is colored by segment.

#include "core/animation/animation_segmenter.h"

namespace trimlab::ui {

/// Thesis 3.2: one segmentation for the whole animation (global), built pose by pose as
/// poses arrive (real-time, 3.2.2), or each pose's partition joined with the next one's
/// (variable, 3.2.3).
enum class SegmentationMode { Global, RealTime, Variable };

struct SegmentationChoices {
    static constexpr int kMaxClusters = 1000;
    static constexpr int kMaxThreads = 256;

    FeatureKind feature = FeatureKind::RotationAngle;
    ReferenceMode reference = ReferenceMode::Rest;
    PartitionMethod method = PartitionMethod::RegionGrowing;
    int clusters = 8;  ///< 1 … kMaxClusters
    int threads = 0;   ///< 0 = every core
    double h = 0.1;    ///< [0, 1]
    SegmentationMode mode = SegmentationMode::Global;
    bool colorBySegment = true;

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

    bool operator==(const SegmentationChoices&) const = default;
};

} // namespace trimlab::ui
