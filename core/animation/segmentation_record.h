#pragma once
/// \file
/// What `trimlab segment` and the GUI's Export both do with a finished segmenter: gather
/// a SegmentationRecord (segmentation_export.h) and write it in the format the output
/// file's extension names (docs/segmentation-format.md).

#include "core/animation/animation_segmenter.h"
#include "core/animation/color_wheel.h"
#include "core/animation/segmentation_export.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace trimlab {

enum class SegmentationFileFormat {
    Json, ///< segmentationJson
    Csv,  ///< segmentationCsv
    Gltf, ///< writeSegmentationGltf: the rest pose with COLOR_0 and _SEGMENT
};

/// The format of `path` by its extension (.json, .csv, .gltf; case-insensitive);
/// nullopt for anything else.
[[nodiscard]] std::optional<SegmentationFileFormat> segmentationFileFormat(const std::filesystem::path& path);

/// The record of `segmenter` (which must be ready()) with the cleaned `segmentation` for
/// `h`. `colors` are the segment colours to write (one per label, e.g. those shown on
/// screen); empty: colorSegments picks them. In variable mode the variable segmentation
/// and its colorSequence are added. Times: the segmenter's stages; `load` and `cleaning`
/// are left 0 for the caller, who measured them. Throws std::invalid_argument when
/// `colors` is neither empty nor one per label.
[[nodiscard]] SegmentationRecord makeSegmentationRecord(const AnimationSegmenter& segmenter, const std::string& source,
                                                        double h, VertexLabeling segmentation,
                                                        std::vector<WheelColor> colors, bool variableMode);

/// Writes `record` to `path` as `format`; the glTF holds the rest pose of `animation`
/// (the animation the record was made from). Throws std::runtime_error naming the file
/// when it cannot be written.
void writeSegmentationFile(const std::filesystem::path& path, SegmentationFileFormat format,
                           const SegmentationRecord& record, const MeshAnimation& animation);

} // namespace trimlab
