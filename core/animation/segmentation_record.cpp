#include "core/animation/segmentation_record.h"

#include "core/io/file_extension.h"
#include "core/animation/segment_coloring.h"
#include "core/animation/segmentation_gltf.h"
#include "core/animation/vertex_areas.h"

#include <algorithm>
#include <stdexcept>

namespace trimlab {

namespace {

void fillCounts(SegmentationRecord& record, const AnimationSegmenter& segmenter)
{
    const MeshAnimation& animation = segmenter.animation();
    record.vertexCount = animation.vertexCount();
    record.faceCount = animation.triangleCount();
    record.poseCount = animation.poseCount();
    record.restPose = animation.restPose;
    record.feature = segmenter.settings().feature;
    record.partition = segmenter.settings().partition;
    record.partitionedPoses = segmenter.partitionedPoses();
    for (std::size_t i = 0; i < segmenter.join().partitionCount(); ++i)
        record.clustersPerPose.push_back(segmenter.join().partition(i).count);
    record.overSegmentCount = segmenter.overSegmentation().count;
}

} // namespace

std::optional<SegmentationFileFormat> segmentationFileFormat(const std::filesystem::path& path)
{
    const std::string extension = io::lowercaseExtension(path);
    if (extension == ".json")
        return SegmentationFileFormat::Json;
    if (extension == ".csv")
        return SegmentationFileFormat::Csv;
    if (extension == ".gltf")
        return SegmentationFileFormat::Gltf;
    return std::nullopt;
}

SegmentationRecord makeSegmentationRecord(const AnimationSegmenter& segmenter, const std::string& source, double h,
                                          VertexLabeling segmentation, std::vector<WheelColor> colors,
                                          bool variableMode)
{
    if (!colors.empty() && colors.size() != segmentation.count)
        throw std::invalid_argument("makeSegmentationRecord: " + std::to_string(colors.size()) + " colours for " +
                                    std::to_string(segmentation.count) + " segments");
    SegmentationRecord record;
    record.source = source;
    fillCounts(record, segmenter);
    record.variableMode = variableMode;
    record.h = h;
    record.colors =
        colors.empty() ? colorSegments(segmenter.graph(), segmentation, segmenter.vertexAreas()) : std::move(colors);
    record.segmentAreas = labelAreas(segmentation.labels, segmentation.count, segmenter.vertexAreas());
    record.segmentation = std::move(segmentation);
    if (variableMode) {
        record.variable = segmenter.variableSegmentation();
        record.variableColors = colorSequence(segmenter.graph(), segmenter.vertexAreas(), record.variable);
    }
    const SegmentationTimes& times = segmenter.times();
    record.times.features = times.featuresMs;
    record.times.partitions = times.partitionsMs;
    record.times.overSegmentation = times.overSegmentationMs;
    return record;
}

void writeSegmentationFile(const std::filesystem::path& path, SegmentationFileFormat format,
                           const SegmentationRecord& record, const MeshAnimation& animation)
{
    switch (format) {
    case SegmentationFileFormat::Json:
        writeTextFile(path, segmentationJson(record));
        break;
    case SegmentationFileFormat::Csv:
        writeTextFile(path, segmentationCsv(record));
        break;
    case SegmentationFileFormat::Gltf:
        writeSegmentationGltf(path, animation.poseMesh(animation.restPose), record.segmentation, record.colors);
        break;
    }
}

} // namespace trimlab
