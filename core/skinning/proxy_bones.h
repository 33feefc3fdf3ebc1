#pragma once
/// \file
/// Where the proxy bones of a skinning fit (skinning_pipeline.h) come from when their
/// number B is given instead of a segmentation: the animation segmented into exactly B
/// segments (segment_count_search.h — one bone per segment, thesis 4.1.1), colored as the
/// Segmentation panel colors a fresh segmentation (colorSegments).

#include "core/animation/animation_segmenter.h"
#include "core/animation/color_wheel.h"
#include "core/animation/segment_count_search.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <vector>

namespace trimlab {

struct BoneSegmentation {
    VertexLabeling labeling;        ///< exactly the requested count of labels
    std::vector<WheelColor> colors; ///< one per label
    /// How the count was reached: clusters, h, merges (its segmentation is moved to
    /// `labeling`); all zero for a segmentation that was given, not searched.
    SegmentCountSearch search;
};

/// For a worker thread: segments a copy of `animation` with `settings` into exactly
/// `count` segments (segmentIntoCount; the segmenter's progress stages). Throws what
/// segmentIntoCount throws (std::invalid_argument for a count of 0 or above #V,
/// std::runtime_error when the animation cannot be partitioned that finely,
/// OperationCancelled).
[[nodiscard]] BoneSegmentation segmentIntoBones(const MeshAnimation& animation, const SegmenterSettings& settings,
                                                std::size_t count, const TaskControl& control);

} // namespace trimlab
