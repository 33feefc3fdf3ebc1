#pragma once
/// \file
/// The segmentation run (thesis chapter 3), as both `trimlab segment` and the
/// Segmentation panel run it: an AnimationSegmenter made from the animation computes the
/// features and pose partitions and joins them (run()), is refused when the feature left
/// no pose to partition, and adds, when asked, the variable segmentation (3.2.3) with its
/// pose-to-pose colours. The segmenter is read-only afterwards, so a caller may call its
/// cheap segment(h) while another run builds a new one. One function composes the run, so
/// the command line and the panel segment alike.

#include "core/animation/animation_segmenter.h"
#include "core/animation/color_wheel.h"
#include "core/animation/mesh_animation.h"
#include "core/animation/vertex_graph.h"
#include "core/util/task_control.h"

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

namespace trimlab {

struct SegmentationRunOptions {
    SegmenterSettings settings;
    /// Also the variable segmentation and its colours (what a per-pose view shows).
    bool variable = true;
};

struct SegmentationResult {
    std::shared_ptr<const AnimationSegmenter> segmenter;
    /// One labeling per partitioned pose (segmenter->partitionedPoses()); empty unless
    /// asked for.
    std::vector<VertexLabeling> variable;
    /// colorSequence of `variable`: colors carried from each pose to the next.
    std::vector<std::vector<WheelColor>> variableColors;

    /// The index into `variable` shown at `pose`: the last partitioned pose at or before
    /// it, or the first one for poses before every partitioned pose (the rest pose).
    /// Requires a non-empty `variable`.
    [[nodiscard]] std::size_t variableIndexAt(std::size_t pose) const;
};

/// The feature leaves no pose to partition: too few poses ("the animation has 1 pose; the
/// rotation feature needs at least 2"). A caller prefixes the animation's name.
class SegmentationInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// For a worker thread: segments `animation` with `options.settings` — run() with its
/// progress stages "features" and "partitions" — then adds the variable segmentation
/// when asked (stage "per-pose segments"). Throws SegmentationInputError as above,
/// OperationCancelled when asked to stop.
[[nodiscard]] std::shared_ptr<const SegmentationResult>
runSegmentation(MeshAnimation animation, const SegmentationRunOptions& options, const TaskControl& control = {});

/// The same for a segmenter that has already run (the end of a real-time stream): adds
/// the variable segmentation. `segmenter` must not be changed afterwards.
[[nodiscard]] std::shared_ptr<const SegmentationResult>
completeSegmentation(std::shared_ptr<const AnimationSegmenter> segmenter, const TaskControl& control = {});

} // namespace trimlab
