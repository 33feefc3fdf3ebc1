#include "app/segment_verb.h"

#include "app/output_paths.h"

#include "app/cli_messages.h"
#include "app/option_values.h"

#include "core/animation/animation_loader.h"
#include "core/animation/animation_segmenter.h"
#include "core/animation/segmentation_record.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>

#include <cmath>
#include <optional>
#include <variant>

namespace trimlab::app {

namespace {

struct SegmentOptions {
    std::string source;
    QString output;
    SegmentationFileFormat format = SegmentationFileFormat::Json;
    SegmenterSettings settings;
    AnimationLoadOptions load;
    double h = 0.0;
    bool variableMode = false;
};

void addSegmentOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription("Segments a mesh animation into parts that move alike (over-segmentation of "
                                     "per-pose partitions, cleaned pose by pose) and writes per-vertex labels.");
    parser.addPositionalArgument("animation", "A folder of .obj/.ply/.off/.stl(.gz) poses, a pattern such as "
                                              "dir/mesh_%04d.obj.gz or dir/mesh_*.obj.gz, or a .gltf/.glb file.");
    parser.addOptions({
        {"clusters", "Clusters per pose partition (required, 1-100000).", "N"},
        {"h", "Cleaning strength in [0, 1] (required): 0 keeps the over-segmentation, larger merges more.", "H"},
        {"feature", "rotation (deformation gradient angle) | velocity | acceleration. Default: rotation.", "name"},
        {"method", "region-growing | hierarchical. Default: region-growing.", "name"},
        {"reference", "rest | previous: the pose rotation angles are measured against. Default: rest.", "name"},
        {"rest-pose", "Index of the rest pose among the loaded poses. Default: 0.", "I"},
        {"mode", "global (one segmentation) | variable (also each pose joined with the next). Default: global.", "name"},
        {"fps", "glTF only: sample the animation at F frames per second instead of at its keyframes.", "F"},
        {"animation", "glTF only: which animation to sample (index). Default: 0.", "I"},
        {"threads", "Worker threads (0 = all cores). Default: 0.", "N"},
        {{"o", "output"}, "Output file (required): .json (docs/segmentation-format.md), .csv or .gltf.", "file"},
    });
    // addHelpOption() would claim -h, which is --h here.
    parser.addOption(QCommandLineOption({QStringLiteral("help"), QStringLiteral("?")}, QStringLiteral("Displays help.")));
}

std::optional<QString> parseChoices(const QCommandLineParser& parser, SegmentOptions& options)
{
    const QString feature = parser.value("feature");
    if (feature == "velocity")
        options.settings.feature.kind = FeatureKind::Velocity;
    else if (feature == "acceleration")
        options.settings.feature.kind = FeatureKind::Acceleration;
    else if (parser.isSet("feature") && feature != "rotation")
        return QStringLiteral("unknown --feature '%1' (use rotation, velocity or acceleration)").arg(feature);
    const QString method = parser.value("method");
    const std::optional<PartitionMethod> parsed = parsePartitionMethod(method.toStdString());
    if (parser.isSet("method") && !parsed)
        return QStringLiteral("unknown --method '%1' (use region-growing or hierarchical)").arg(method);
    options.settings.partition.method = parsed.value_or(PartitionMethod::RegionGrowing);
    const QString reference = parser.value("reference");
    if (parser.isSet("reference") && reference != "rest" && reference != "previous")
        return QStringLiteral("unknown --reference '%1' (use rest or previous)").arg(reference);
    options.settings.feature.reference = reference == "previous" ? ReferenceMode::Previous : ReferenceMode::Rest;
    const QString mode = parser.value("mode");
    if (parser.isSet("mode") && mode != "global" && mode != "variable")
        return QStringLiteral("unknown --mode '%1' (use global or variable)").arg(mode);
    options.variableMode = mode == "variable";
    return std::nullopt;
}

std::optional<QString> parseOutput(const QCommandLineParser& parser, SegmentOptions& options)
{
    options.output = parser.value("output");
    if (options.output.isEmpty())
        return QStringLiteral("segment needs an output file: -o labels.json (or .csv, .gltf)");
    const std::optional<SegmentationFileFormat> format = segmentationFileFormat(options.output.toStdString());
    if (!format)
        return QStringLiteral("-o must name a .json, .csv or .gltf file, got '%1'").arg(options.output);
    options.format = *format;
    if (auto e = checkOutputPaths({{"-o", options.output}}))
        return e;
    return std::nullopt;
}

std::optional<QString> parseNumbers(const QCommandLineParser& parser, SegmentOptions& options)
{
    if (!parser.isSet("clusters") || !parser.isSet("h"))
        return QStringLiteral("segment needs --clusters N and --h H; see trimlab segment --help");
    long long clusters = 0;
    long long restPose = 0;
    long long animation = 0;
    long long threads = 0;
    for (const auto& error : {parseIntegerFlag(parser, "clusters", 1, 100000, clusters),
                              parseIntegerFlag(parser, "rest-pose", 0, 1000000000, restPose),
                              parseIntegerFlag(parser, "animation", 0, 1000000, animation),
                              parseIntegerFlag(parser, "threads", 0, 1024, threads),
                              parseRealFlag(parser, "h", 0.0, 1.0, options.h),
                              parseRealFlag(parser, "fps", 1e-3, 10000.0, options.load.gltf.fps)}) {
        if (error)
            return error;
    }
    options.settings.partition.clusters = std::size_t(clusters);
    options.load.restPose = std::size_t(restPose);
    options.load.gltf.animation = int(animation);
    options.settings.threads = unsigned(threads);
    options.load.threads = unsigned(threads);
    return std::nullopt;
}

std::variant<SegmentOptions, QString> parseSegmentOptions(const QStringList& arguments, bool& helpShown)
{
    QCommandLineParser parser;
    addSegmentOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab segment")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        printLine(verbHelpText(parser, QStringLiteral("segment")));
        helpShown = true;
        return QString();
    }
    if (parser.positionalArguments().size() != 1)
        return QStringLiteral("segment needs exactly one animation (a folder, a pattern or a glTF file); see trimlab "
                              "segment --help");
    SegmentOptions options;
    options.source = parser.positionalArguments().first().toStdString();
    for (const auto& error : {parseNumbers(parser, options), parseChoices(parser, options), parseOutput(parser, options)}) {
        if (error)
            return *error;
    }
    return options;
}

double elapsedMs(const QElapsedTimer& timer)
{
    return double(timer.nsecsElapsed()) * 1e-6;
}

void requireFeaturePoses(const AnimationSegmenter& segmenter, const SegmentOptions& options)
{
    if (!segmenter.partitionedPoses().empty())
        return;
    const std::size_t poses = segmenter.animation().poseCount();
    const std::size_t needed = options.settings.feature.kind == FeatureKind::Acceleration ? 3 : 2;
    throw std::runtime_error(options.source + ": the animation has " + std::to_string(poses) + " pose" +
                             (poses == 1 ? "" : "s") + "; the " +
                             std::string(featureName(options.settings.feature.kind)) + " feature needs at least " +
                             std::to_string(needed));
}

void printSummary(const SegmentationRecord& r)
{
    printLine(QStringLiteral("%1: %2 poses, %3 vertices, %4 faces; %5 (%6), %7, %8 clusters per pose")
                  .arg(QString::fromStdString(r.source))
                  .arg(r.poseCount)
                  .arg(r.vertexCount)
                  .arg(r.faceCount)
                  .arg(QString::fromLatin1(featureName(r.feature.kind).data()),
                       QString::fromLatin1(referenceName(r.feature.reference).data()),
                       QString::fromLatin1(partitionMethodName(r.partition.method).data()))
                  .arg(r.partition.clusters));
    printLine(QStringLiteral("segments: %1 (over-segmentation %2, h = %3)")
                  .arg(r.segmentation.count)
                  .arg(r.overSegmentCount)
                  .arg(r.h));
    printLine(QStringLiteral("times (ms): load %1, features %2, partitions %3, over-segmentation %4, cleaning %5")
                  .arg(r.times.load, 0, 'f', 1)
                  .arg(r.times.features, 0, 'f', 1)
                  .arg(r.times.partitions, 0, 'f', 1)
                  .arg(r.times.overSegmentation, 0, 'f', 1)
                  .arg(r.times.cleaning, 0, 'f', 2));
}

int segmentAnimation(const SegmentOptions& options)
{
    QElapsedTimer timer;
    timer.start();
    MeshAnimation animation = loadAnimation(options.source, options.load);
    const double loadMs = elapsedMs(timer);
    AnimationSegmenter segmenter(std::move(animation), options.settings);
    segmenter.run();
    requireFeaturePoses(segmenter, options);
    timer.restart();
    VertexLabeling segmentation = segmenter.segment(options.h);
    const double cleaningMs = elapsedMs(timer);
    SegmentationRecord record =
        makeSegmentationRecord(segmenter, options.source, options.h, std::move(segmentation), {}, options.variableMode);
    record.times.load = loadMs;
    record.times.cleaning = cleaningMs;
    writeSegmentationFile(options.output.toStdString(), options.format, record, segmenter.animation());
    printSummary(record);
    printLine(QStringLiteral("wrote %1").arg(options.output));
    return 0;
}

} // namespace

int runSegmentVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    bool helpShown = false;
    auto parsed = parseSegmentOptions(arguments, helpShown);
    if (helpShown)
        return 0;
    if (const QString* error = std::get_if<QString>(&parsed)) {
        printError(*error);
        return 2;
    }
    return runGuarded([&] { return segmentAnimation(std::get<SegmentOptions>(parsed)); });
}

} // namespace trimlab::app
