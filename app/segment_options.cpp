#include "app/segment_options.h"

#include "app/cli_messages.h"
#include "app/output_paths.h"
#include "app/parameter_options.h"

#include <QCommandLineParser>

#include <optional>

namespace trimlab::app {

namespace {

void addSegmentOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription("Segments a mesh animation into parts that move alike (over-segmentation of "
                                     "per-pose partitions, cleaned pose by pose) and writes per-vertex labels.");
    parser.addPositionalArgument("animation", "A folder of .obj/.ply/.off/.stl(.gz) poses, a pattern such as "
                                              "dir/mesh_%04d.obj.gz or dir/mesh_*.obj.gz, or a .gltf/.glb file.");
    addParameterOptions(parser, segment_verb_parameters::kTable);
    parser.addOption(QCommandLineOption(
        {QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("Output file (required): .json (docs/segmentation-format.md), .csv or .gltf."), "file"));
    // addHelpOption() would claim -h, which is --h here.
    parser.addOption(
        QCommandLineOption({QStringLiteral("help"), QStringLiteral("?")}, QStringLiteral("Displays help.")));
}

// Every flagged row of segment_verb_parameters::kTable, before any other check.
std::optional<QString> parseParameters(const QCommandLineParser& parser, SegmentOptions& options)
{
    using namespace segmentation_parameters;
    SegmentationMode mode = SegmentationMode(kMode.defaultValue);
    for (const std::optional<QString>& error :
         {parseParameter(parser, kClusters, options.settings.partition.clusters), parseParameter(parser, kH, options.h),
          parseParameter(parser, kFeature, options.settings.feature.kind),
          parseParameter(parser, kMethod, options.settings.partition.method),
          parseParameter(parser, kReference, options.settings.feature.reference),
          parseParameter(parser, animation_load_parameters::kRestPose, options.load.restPose),
          parseParameter(parser, kMode, mode),
          parseParameter(parser, animation_load_parameters::kGltfFps, options.load.gltf.fps),
          parseParameter(parser, animation_load_parameters::kGltfAnimation, options.load.gltf.animation),
          parseParameter(parser, hole_closing_parameters::kCloseHoles, options.load.closeHoles),
          parseParameter(parser, kThreads, options.settings.threads)}) {
        if (error)
            return error;
    }
    options.variableMode = mode == SegmentationMode::Variable;
    options.load.threads = options.settings.threads;
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
    return checkOutputPaths({{"-o", options.output}});
}

} // namespace

std::variant<SegmentOptions, QString> parseSegmentOptions(const QStringList& arguments, QString& help)
{
    QCommandLineParser parser;
    addSegmentOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab segment")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        help = verbHelpText(parser, QStringLiteral("segment"));
        return QString();
    }
    SegmentOptions options;
    if (auto e = parseParameters(parser, options))
        return *e;
    if (parser.positionalArguments().size() != 1)
        return QStringLiteral("segment needs exactly one animation (a folder, a pattern or a glTF file); see trimlab "
                              "segment --help");
    if (!parser.isSet("clusters") || !parser.isSet("h"))
        return QStringLiteral("segment needs --clusters N and --h H; see trimlab segment --help");
    options.source = parser.positionalArguments().first().toStdString();
    if (auto e = parseOutput(parser, options))
        return *e;
    return options;
}

} // namespace trimlab::app
