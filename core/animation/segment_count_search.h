#pragma once
/// \file
/// A segmentation with exactly a requested number of segments — the bone count B of a
/// skinning (thesis 4.1.1: one proxy bone per segment). The chapter 3 pipeline is steered
/// by two parameters, the clusters per pose partition and the cleaning strength h, and
/// neither gives a segment count directly; this searches them, then closes any remaining
/// gap by merging the smallest segments.

#include "core/animation/animation_segmenter.h"
#include "core/util/task_control.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <span>

namespace trimlab {

struct SegmentCountSearch {
    VertexLabeling segmentation;  ///< exactly the requested count of segments (canonical labels)
    std::size_t clusters = 0;     ///< clusters per pose partition of the segmenter's last run
    std::size_t overSegments = 0; ///< segments of that run's over-segmentation
    double h = 0.0;               ///< the cleaning strength of the segmentation merged from
    std::size_t cleanedCount = 0; ///< segments p2p-cleaning left at `h` (≥ the count)
    std::size_t merged = 0;       ///< motion merges from `cleanedCount` down to the count
};

/// Segments `segmenter`'s animation into exactly `count` segments:
/// 1. Partitions with `count` clusters per pose, the segmenter's other settings kept:
///    run() when it is not ready (construct it with `count` clusters and this is its only
///    partitioning), then repartition() unless it already used `count`; and, while the
///    over-segmentation has fewer than `count` segments, repartitions with twice the
///    clusters (at most #V).
/// 2. Bisects h ∈ [0, 1] on the cleaned segment count (falling with h, though not
///    strictly: p2p_cleaning.h), keeping the largest h whose count is still ≥ 2·`count`
///    (or ≥ the over-segmentation's count when that is smaller).
/// 3. Merges segments by motion (mergeByMotion, motion_merge.h) until `count` remain: a
///    cleaning strength alone leaves slivers of a few vertices beside large segments
///    (samba at 30: 14 of 30 segments under 1 % of the vertices, the largest 2,820 of
///    9,971; with the motion merges 9, and 1,552), and each sliver then joins the part it
///    moves with. Segments under a tenth of the average size (#V / (10·count)) are merged
///    first. `count` == 1 gives one segment without running anything.
/// Throws std::invalid_argument when `count` is 0 or above #V, std::runtime_error when the
/// animation has too few poses to be partitioned or the over-segmentation cannot reach
/// `count` segments; OperationCancelled from the segmenter's stages.
[[nodiscard]] SegmentCountSearch segmentIntoCount(AnimationSegmenter& segmenter, std::size_t count,
                                                  const TaskControl& control = {});

} // namespace trimlab
