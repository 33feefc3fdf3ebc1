#include "app/skin_options.h"

#include "app/cli_messages.h"
#include "app/output_paths.h"
#include "app/parameter_options.h"

#include <QCommandLineParser>

#include <optional>

namespace trimlab::app {

namespace {

void addSkinOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Approximates a mesh animation by skinning: B proxy bones from a segmentation into exactly B segments, "
        "a fit of every pose, corrections, and a glTF 2.0 export. By default it fits the model a glTF skin plays "
        "(rigid joints, linear blend), which gives the lowest exported error. Prints E_RMS of the fit and of the "
        "exported file. See docs/skinning.md.");
    parser.addPositionalArgument("animation", "A folder of .obj/.ply/.off/.stl(.gz) poses, a pattern such as "
                                              "dir/mesh_%04d.obj.gz or dir/mesh_*.obj.gz, or a .gltf/.glb file.");
    addParameterOptions(parser, skin_verb_parameters::kTable);
    parser.addOptions({
        {"corrections",
         "none | v (rest-pose vertex corrections) | w (weight corrections) | v,w. Default: v,w "
         "for rigid, none for lbs and dqs.",
         "list"},
        {{"o", "output"}, "Output file (required): .glb (binary) or .gltf (embedded buffer).", "file"},
    });
    parser.addHelpOption();
}

// The flagged rows of skin_verb_parameters::kTable, before any other check; the fit's
// method and chain are set by parseFit.
std::optional<QString> parseParameters(const QCommandLineParser& parser, SkinOptions& options, SkinningFitKind& fit)
{
    using namespace skinning_parameters;
    std::size_t influences = kDefaultInfluences;
    bool morph = options.exported.morphTargets;
    bool step = options.exported.stepInterpolation;
    for (const std::optional<QString>& error :
         {parseParameter(parser, kBones, options.bones), parseParameter(parser, kFit, fit),
          parseParameter(parser, kChain, options.fit.chain), parseParameter(parser, kInfluences, influences),
          parseParameter(parser, kExportFps, options.fps), parseParameter(parser, kExport, morph),
          parseParameter(parser, kInterpolation, step),
          parseParameter(parser, animation_load_parameters::kRestPose, options.load.restPose),
          parseParameter(parser, hole_closing_parameters::kCloseHoles, options.load.closeHoles),
          parseParameter(parser, skin_verb_parameters::kThreads, options.fit.threads)}) {
        if (error)
            return error;
    }
    options.fit.decomposition.maxInfluences = influences;
    options.exported.morphTargets = morph;
    options.exported.stepInterpolation = step;
    options.load.threads = options.fit.threads;
    return std::nullopt;
}

// The fit and what applies to it: the chain of lbs and dqs, the corrections, the influences.
std::optional<QString> parseFit(const QCommandLineParser& parser, SkinningFitKind fit, SkinOptions& options)
{
    chooseSkinningFit(options.fit, fit);
    if (parser.isSet("chain") && options.fit.fitExported)
        return QStringLiteral("--chain applies to --method lbs or dqs; the rigid fit always maps the rest pose to "
                              "each pose");
    if (parser.isSet("corrections")) {
        const QString corrections = parser.value("corrections");
        if (corrections != "none" && corrections != "v" && corrections != "w" && corrections != "v,w" &&
            corrections != "w,v")
            return QStringLiteral("unknown --corrections '%1' (use none, v, w or v,w)").arg(corrections);
        options.fit.vertexCorrections = corrections.contains('v');
        options.fit.weightCorrections = corrections.contains('w');
    }
    if (parser.isSet("influences") && !usesDecomposition(options.fit))
        return QStringLiteral("--influences applies to --method rigid (the default) and to --method lbs --chain "
                              "rest-to-pose with corrections; the other fits keep the segmentation's 4");
    return std::nullopt;
}

std::optional<QString> parseOutput(const QCommandLineParser& parser, SkinOptions& options)
{
    options.output = parser.value("output");
    if (options.output.isEmpty())
        return QStringLiteral("skin needs an output file: -o out.glb (or .gltf)");
    if (!options.output.endsWith(".glb", Qt::CaseInsensitive) && !options.output.endsWith(".gltf", Qt::CaseInsensitive))
        return QStringLiteral("-o must name a .glb or .gltf file, got '%1'").arg(options.output);
    return checkOutputPaths({{"-o", options.output}});
}

} // namespace

std::variant<SkinOptions, QString> parseSkinOptions(const QStringList& arguments, QString& help)
{
    QCommandLineParser parser;
    addSkinOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab skin")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        help = verbHelpText(parser, QStringLiteral("skin"));
        return QString();
    }
    SkinOptions options;
    SkinningFitKind fit = SkinningFitKind(skinning_parameters::kFit.defaultValue);
    if (auto e = parseParameters(parser, options, fit))
        return *e;
    if (parser.positionalArguments().size() != 1)
        return QStringLiteral("skin needs exactly one animation (a folder, a pattern or a glTF file); see trimlab skin "
                              "--help");
    if (!parser.isSet("bones"))
        return QStringLiteral("skin needs --bones B; see trimlab skin --help");
    options.source = parser.positionalArguments().first().toStdString();
    for (const auto& error : {parseFit(parser, fit, options), parseOutput(parser, options)}) {
        if (error)
            return *error;
    }
    return options;
}

} // namespace trimlab::app
