#include "app/skeleton_options.h"

#include "app/cli_messages.h"
#include "app/output_paths.h"
#include "app/parameter_options.h"

#include "core/animation/animation_load_parameters.h"
#include "core/animation/sequence_files.h"
#include "core/trim/hole_closing.h"

#include <QCommandLineParser>

#include <optional>

namespace trimlab::app {

namespace {

void addSkeletonOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Extracts an animation skeleton from a closed mesh by mesh contraction (Berenguer & Moreno): contraction, "
        "simplification, refinement and selection of about N joints; then bone-heat skinning weights, and exports "
        "the rigged mesh as glTF 2.0 and the skeleton as JSON. Prints the time of every stage as in the paper's "
        "Table III. Given an animation, makes the rig from its rest pose and reports how well the rig reproduces "
        "every pose (E_RMS, as trimlab skin reports it). See docs/skeleton.md.");
    parser.addPositionalArgument("mesh", "A closed, manifold, connected mesh (.obj .ply .stl .off .gltf .glb, "
                                         "optionally .gz) or demo:NAME; or an animation: a folder of poses or a "
                                         "pattern such as dir/mesh_%04d.obj.gz.");
    addParameterOptions(parser, skeleton_parameters::kTable);
    parser.addOption(commandLineOption(hole_closing_parameters::kCloseHoles));
    parser.addOption(commandLineOption(animation_load_parameters::kRestPose));
    parser.addOptions({
        {{"o", "output"}, "Write the rigged mesh: .glb (binary) or .gltf (embedded buffer).", "file"},
        {"json", "Write the skeleton (joints, tree, bones, vertex-joint map, curve skeleton) as JSON.", "file"},
    });
    parser.addHelpOption();
}

// Every flagged row of skeleton_parameters::kTable, before any other check.
std::optional<QString> parseParameters(const QCommandLineParser& parser, SkeletonVerbOptions& o)
{
    using namespace skeleton_parameters;
    ContractionOptions& c = o.extraction.contraction;
    SimplificationOptions& s = o.extraction.simplification;
    for (const std::optional<QString>& error :
         {parseParameter(parser, kInitialContractionWeight, c.initialContractionWeight),
          parseParameter(parser, kContractionGrowth, c.contractionGrowth),
          parseParameter(parser, kMaxContractionWeight, c.maxContractionWeight),
          parseParameter(parser, kMaxAttractionWeight, c.maxAttractionWeight),
          parseParameter(parser, kMaxIterations, c.maxIterations), parseParameter(parser, kOrdering, c.ordering),
          parseParameter(parser, kSolver, c.backend),
          parseParameter(parser, kPreCollapseFraction, s.preCollapseFraction),
          parseParameter(parser, kShapeWeight, s.shapeWeight),
          parseParameter(parser, kSamplingWeight, s.samplingWeight),
          parseParameter(parser, kRefine, o.extraction.refine),
          parseParameter(parser, kTargetNodes, o.extraction.targetNodes),
          parseParameter(parser, kRootJoint, o.extraction.rootJoint),
          parseParameter(parser, kHeatConstant, o.heatConstant),
          parseParameter(parser, kLoopSubdivisions, o.loopLevels),
          parseParameter(parser, hole_closing_parameters::kCloseHoles, o.closeHoles),
          parseParameter(parser, animation_load_parameters::kRestPose, o.restPose)}) {
        if (error)
            return error;
    }
    return std::nullopt;
}

std::optional<QString> parseOutputs(const QCommandLineParser& parser, SkeletonVerbOptions& o)
{
    o.output = parser.value("output");
    if (!o.output.isEmpty() && !o.output.endsWith(".glb", Qt::CaseInsensitive) &&
        !o.output.endsWith(".gltf", Qt::CaseInsensitive))
        return QStringLiteral("-o must name a .glb or .gltf file, got '%1'").arg(o.output);
    o.json = parser.value("json");
    if (parser.isSet("json") && o.json.isEmpty())
        return QStringLiteral("--json needs a file name");
    return checkOutputPaths({{"-o", o.output}, {"--json", o.json}});
}

} // namespace

std::variant<SkeletonVerbOptions, QString> parseSkeletonOptions(const QStringList& arguments, QString& help)
{
    QCommandLineParser parser;
    addSkeletonOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab skeleton")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        help = verbHelpText(parser, QStringLiteral("skeleton"));
        return QString();
    }
    SkeletonVerbOptions options;
    if (auto e = parseParameters(parser, options))
        return *e;
    if (parser.positionalArguments().size() != 1)
        return QStringLiteral("skeleton needs exactly one mesh (a file or demo:NAME); see trimlab skeleton --help");
    options.source = parser.positionalArguments().first().toStdString();
    options.animation = isMeshSequenceSource(options.source);
    if (!options.animation && parser.isSet(QString::fromLatin1(animation_load_parameters::kRestPose.flag.data())))
        return QStringLiteral("--rest-pose needs an animation (a folder or pattern of poses), not one mesh");
    if (options.animation && options.loopLevels > 0)
        return QStringLiteral("--loop-subdivide needs one mesh: the poses of an animation are not subdivided");
    const int nodes = options.extraction.targetNodes;
    if (options.extraction.rootJoint >= nodes)
        return QStringLiteral("--root %1 is not one of the %2 joints (0 to %3)")
            .arg(options.extraction.rootJoint)
            .arg(nodes)
            .arg(nodes - 1);
    if (auto e = parseOutputs(parser, options))
        return *e;
    return options;
}

} // namespace trimlab::app
