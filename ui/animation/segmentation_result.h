#pragma once
/// \file
/// A finished segmentation as the Segmentation panel keeps it: the segmenter (read only
/// from then on, so the UI thread may call its cheap segment(h) while the next run
/// builds a new segmenter on a worker) and the variable segmentation (thesis 3.2.3) with
/// its pose-to-pose colors, computed with it on the worker.

#include "core/animation/animation_segmenter.h"
#include "core/animation/color_wheel.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace trimlab::ui {

struct SegmentationResult {
    std::shared_ptr<const AnimationSegmenter> segmenter;
    /// One labeling per partitioned pose (segmenter->partitionedPoses()).
    std::vector<VertexLabeling> variable;
    /// colorSequence of `variable`: colors carried from each pose to the next.
    std::vector<std::vector<WheelColor>> variableColors;

    /// The index into `variable` shown at `pose`: the last partitioned pose at or before
    /// it, or the first one for poses before every partitioned pose (the rest pose).
    /// Requires a non-empty `variable`.
    [[nodiscard]] std::size_t variableIndexAt(std::size_t pose) const;
};

/// For a worker thread: segments `animation` (copied) with `settings` — run() with its
/// progress stages "features" and "partitions" — then adds the variable segmentation
/// (stage "variable"). Throws std::runtime_error when the feature leaves no pose to
/// partition (too few poses), OperationCancelled when asked to stop.
[[nodiscard]] std::shared_ptr<const SegmentationResult> runSegmentation(const MeshAnimation& animation,
                                                                        const SegmenterSettings& settings,
                                                                        const TaskControl& control);

/// The same for a segmenter that has already run (the end of a real-time stream): adds
/// the variable segmentation. `segmenter` must not be changed afterwards.
[[nodiscard]] std::shared_ptr<const SegmentationResult> completeSegmentation(
    std::shared_ptr<const AnimationSegmenter> segmenter, const TaskControl& control);

} // namespace trimlab::ui
