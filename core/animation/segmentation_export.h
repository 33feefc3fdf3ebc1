#pragma once
/// \file
/// Writing a segmentation for other tools: per-vertex labels as CSV, and the JSON
/// document described in docs/segmentation-format.md (settings, counts, per-segment
/// colours, per-vertex labels, per-stage times).

#include "core/animation/color_wheel.h"
#include "core/animation/pose_features.h"
#include "core/animation/pose_partition.h"
#include "core/animation/vertex_graph.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace trimlab {

/// Wall-clock milliseconds per pipeline stage.
struct StageTimings {
    double load = 0.0;
    double features = 0.0;
    double partitions = 0.0;
    double overSegmentation = 0.0;
    double cleaning = 0.0;
};

/// Everything an export holds. `variable`/`variableColors` are filled only in variable
/// mode (one labeling per partitioned pose).
struct SegmentationRecord {
    std::string source;
    std::size_t vertexCount = 0;
    std::size_t faceCount = 0;
    std::size_t poseCount = 0;
    std::size_t restPose = 0;
    FeatureSettings feature;
    PartitionSettings partition;
    bool variableMode = false;
    double h = 0.0;
    std::vector<std::size_t> partitionedPoses;
    std::vector<std::uint32_t> clustersPerPose; ///< clusters each partition actually has
    std::size_t overSegmentCount = 0;
    VertexLabeling segmentation;
    std::vector<WheelColor> colors;   ///< one per segment
    std::vector<double> segmentAreas; ///< one per segment (rest pose)
    std::vector<VertexLabeling> variable;
    std::vector<std::vector<WheelColor>> variableColors;
    StageTimings times;
};

/// The JSON document (UTF-8, one object; see docs/segmentation-format.md).
[[nodiscard]] std::string segmentationJson(const SegmentationRecord& record);

/// CSV: a header line "vertex,label" (in variable mode followed by ",pose_N" per
/// partitioned pose N), then one line per vertex.
[[nodiscard]] std::string segmentationCsv(const SegmentationRecord& record);

/// "#rrggbb" of a colour (8 bits per channel, rounded).
[[nodiscard]] std::string hexColor(const WheelColor& color);

/// Writes `text` to `path` through a temporary file and a rename (atomic_write.h), so a
/// failed or killed write leaves an earlier file whole. Throws std::runtime_error naming
/// the file when it cannot be written.
void writeTextFile(const std::filesystem::path& path, const std::string& text);

} // namespace trimlab
