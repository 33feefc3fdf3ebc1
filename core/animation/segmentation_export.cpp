#include "core/animation/segmentation_export.h"

#include "core/io/atomic_write.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace trimlab {

namespace {

std::string jsonString(const std::string& text)
{
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string number(double value)
{
    if (!std::isfinite(value))
        return "null";
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

template <class T>
std::string integerArray(const std::vector<T>& values)
{
    std::string out = "[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            out += ',';
        out += std::to_string(values[i]);
    }
    return out + "]";
}

std::string rgbArray(const WheelColor& color)
{
    const glm::vec3 rgb = color.rgb();
    auto byte = [](float c) { return std::to_string(int(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f))); };
    return "[" + byte(rgb.r) + "," + byte(rgb.g) + "," + byte(rgb.b) + "]";
}

std::string segmentsArray(const SegmentationRecord& r)
{
    std::vector<std::size_t> vertexCounts(r.segmentation.count, 0);
    for (const std::uint32_t label : r.segmentation.labels)
        ++vertexCounts[label];
    std::string out = "[";
    for (std::size_t s = 0; s < r.segmentation.count; ++s) {
        out += s > 0 ? ",\n    " : "\n    ";
        out += "{\"label\": " + std::to_string(s) + ", \"color\": " + rgbArray(r.colors.at(s)) +
               ", \"hex\": " + jsonString(hexColor(r.colors.at(s))) +
               ", \"vertex_count\": " + std::to_string(vertexCounts[s]) +
               ", \"area\": " + number(s < r.segmentAreas.size() ? r.segmentAreas[s] : NAN) + "}";
    }
    return out + "\n  ]";
}

std::string variableArray(const SegmentationRecord& r)
{
    std::string out = "[";
    for (std::size_t i = 0; i < r.variable.size(); ++i) {
        std::string colors = "[";
        for (std::size_t c = 0; c < r.variableColors.at(i).size(); ++c)
            colors += (c > 0 ? "," : "") + rgbArray(r.variableColors[i][c]);
        out += i > 0 ? ",\n    " : "\n    ";
        out += "{\"pose\": " + std::to_string(r.partitionedPoses.at(i)) +
               ", \"segment_count\": " + std::to_string(r.variable[i].count) + ", \"colors\": " + colors +
               "], \"labels\": " + integerArray(r.variable[i].labels) + "}";
    }
    return out + "\n  ]";
}

std::string timesObject(const StageTimings& t)
{
    return "{\"load\": " + number(t.load) + ", \"features\": " + number(t.features) +
           ", \"partitions\": " + number(t.partitions) + ", \"over_segmentation\": " + number(t.overSegmentation) +
           ", \"cleaning\": " + number(t.cleaning) + "}";
}

} // namespace

std::string hexColor(const WheelColor& color)
{
    const glm::vec3 rgb = color.rgb();
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", unsigned(std::lround(std::clamp(rgb.r, 0.0f, 1.0f) * 255.0f)),
                  unsigned(std::lround(std::clamp(rgb.g, 0.0f, 1.0f) * 255.0f)),
                  unsigned(std::lround(std::clamp(rgb.b, 0.0f, 1.0f) * 255.0f)));
    return text;
}

std::string segmentationJson(const SegmentationRecord& r)
{
    std::string out = "{\n";
    auto field = [&](const std::string& name, const std::string& value) {
        out += "  " + jsonString(name) + ": " + value + ",\n";
    };
    field("format", jsonString("trimlab-segmentation"));
    field("version", "1");
    field("source", jsonString(r.source));
    field("vertex_count", std::to_string(r.vertexCount));
    field("face_count", std::to_string(r.faceCount));
    field("pose_count", std::to_string(r.poseCount));
    field("rest_pose", std::to_string(r.restPose));
    field("feature", jsonString(std::string(featureName(r.feature.kind))));
    field("reference", jsonString(std::string(referenceName(r.feature.reference))));
    field("method", jsonString(std::string(partitionMethodName(r.partition.method))));
    field("clusters", std::to_string(r.partition.clusters));
    field("mode", jsonString(r.variableMode ? "variable" : "global"));
    field("h", number(r.h));
    field("partitioned_poses", integerArray(r.partitionedPoses));
    field("clusters_per_pose", integerArray(r.clustersPerPose));
    field("over_segment_count", std::to_string(r.overSegmentCount));
    field("segment_count", std::to_string(r.segmentation.count));
    field("segments", segmentsArray(r));
    field("times_ms", timesObject(r.times));
    if (r.variableMode)
        field("variable", variableArray(r));
    out += "  \"labels\": " + integerArray(r.segmentation.labels) + "\n}\n";
    return out;
}

std::string segmentationCsv(const SegmentationRecord& r)
{
    std::string out = "vertex,label";
    if (r.variableMode) {
        for (std::size_t i = 0; i < r.variable.size(); ++i)
            out += ",pose_" + std::to_string(r.partitionedPoses.at(i));
    }
    out += '\n';
    for (std::size_t v = 0; v < r.segmentation.labels.size(); ++v) {
        out += std::to_string(v) + ',' + std::to_string(r.segmentation.labels[v]);
        if (r.variableMode) {
            for (const VertexLabeling& labeling : r.variable)
                out += ',' + std::to_string(labeling.labels[v]);
        }
        out += '\n';
    }
    return out;
}

void writeTextFile(const std::filesystem::path& path, const std::string& text)
{
    io::writeFileAtomically(path, text);
}

} // namespace trimlab
