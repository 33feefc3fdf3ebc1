#include "app/trim_verb.h"

#include "app/cli_messages.h"
#include "app/output_paths.h"
#include "app/parameter_options.h"
#include "app/pose_frames.h"
#include "app/scene_composition.h"
#include "app/terminal_progress.h"

#include "core/animation/animation_loader.h"
#include "core/catalog/scene_source.h"
#include "core/io/file_extension.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_sequence_gltf.h"
#include "core/skinning/skinning_parameters.h"
#include "core/solid/trimmed_animation.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/clip_set.h"
#include "core/trim/csg_expression.h"
#include "core/trim/hole_closing.h"
#include "core/trim/static_rule.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <filesystem>
#include <variant>

namespace trimlab::app {

namespace {

struct TrimOptions {
    std::vector<std::string> sources;
    std::vector<ObjectTransformOption> transforms;
    TrimSettings trim;
    bool ruleGiven = false;
    bool csgGiven = false;
    bool closeHoles = false;
    QString output;
    std::optional<PoseSelection> poses; ///< the source is an animation: trim these poses
    double fps = 24.0;                  ///< of the glTF sequence of --poses
};

void addTrimOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        "Exports the trimmed solid as exact geometry: the scene's triangles refined along all their intersections "
        "(exact arithmetic), every cell of space classified by its winding number under the rule (or the CSG "
        "expression), and the faces between kept and dropped cells written as a closed mesh facing outward.");
    parser.addPositionalArgument("sources",
                                 "Mesh files or demo:NAME (several make one scene, object ids counting "
                                 "across them in order), or a .trimlab project.",
                                 "SOURCE...");
    parser.addOptions({
        {"rule",
         QStringLiteral("The static rule: %1. Default: alternating-border, or the rule a scene project saved.")
             .arg(QString::fromStdString(staticRuleNamesHelp())),
         "rule"},
        {"csg", "CSG of the objects, as trimlab render --csg (each object by --object-rule, else --rule).",
         "expression"},
        {"object-rule", "Rule of one object for --csg, e.g. 1=parity. Repeatable.", "id=rule"},
        {"object-transform", objectTransformHelp(), "id=tx,ty,tz[,rx,ry,rz[,s]]"},
        {"clip",
         QStringLiteral("Cut the solid by the plane a,b,c,d, keeping a*x+b*y+c*z+d >= 0 (world space), and close it "
                        "by a cap on the plane: the solid as `render --clip --cap` shows it. Repeat for up to %1 "
                        "planes.")
             .arg(kMaxClipPlanes),
         "a,b,c,d"},
        {{"o", "output"},
         QStringLiteral("The mesh to write: %1. With --poses, one file per pose with the pose number in its name "
                        "as %d or %04d (trimmed_%04d.obj), or one .gltf/.glb without it that plays the poses in turn.")
             .arg(QString::fromStdString(meshExportFormatsText())),
         "file"},
        {"pose",
         "The source is a mesh animation (a folder or numbered pattern of meshes, or a glTF file): export its pose "
         "N (0 = the first) trimmed by --rule.",
         "N"},
        {"poses",
         "The source is a mesh animation: export poses A to B, each trimmed on its own by --rule (the dynamic rules "
         "have no exact export).",
         "A:B"},
    });
    parser.addOption(commandLineOption(skinning_parameters::kExportFps));
    parser.addOption(commandLineOption(hole_closing_parameters::kCloseHoles));
    parser.addHelpOption();
}

bool isGltfPath(const QString& path)
{
    const std::string extension = io::lowercaseExtension(path.toStdString());
    return extension == ".gltf" || extension == ".glb";
}

// --pose / --poses: one animation source, one object, and -o a pose-numbered name or one
// glTF for the whole sequence.
std::optional<QString> parsePoseOptions(const QCommandLineParser& parser, TrimOptions& options)
{
    if (auto e = parsePoseSelection(parser.value("pose"), parser.value("poses"), options.poses))
        return e;
    if (auto e = parseParameter(parser, skinning_parameters::kExportFps, options.fps))
        return e;
    if (!options.poses) {
        if (parser.isSet("fps"))
            return QStringLiteral("--fps is the rate of the glTF sequence of --poses; give --poses A:B");
        return std::nullopt;
    }
    if (options.sources.size() != 1)
        return QStringLiteral("--pose and --poses export one mesh animation source (a folder, a numbered pattern or "
                              "a glTF file), not several sources");
    if (options.csgGiven || !options.transforms.empty() || !parser.values("object-rule").isEmpty())
        return QStringLiteral("--csg, --object-rule and --object-transform combine several objects; an animation is "
                              "one object");
    if (options.poses->sequence && !hasPoseNumber(options.output) && !isGltfPath(options.output))
        return QStringLiteral("--poses writes one file per pose: -o '%1' needs the pose number in its name as %d or "
                              "%04d (trimmed_%04d.obj), or a .gltf/.glb name for one file that plays the sequence")
            .arg(options.output);
    if (!options.poses->sequence && hasPoseNumber(options.output))
        options.output = posePath(options.output, options.poses->first);
    return std::nullopt;
}

std::variant<TrimOptions, QString> parseTrimOptions(const QStringList& arguments, QString* help)
{
    QCommandLineParser parser;
    addTrimOptions(parser);
    if (!parser.parse(QStringList{QStringLiteral("trimlab trim")} + arguments))
        return parser.errorText();
    if (parser.isSet("help")) {
        *help = verbHelpText(parser, QStringLiteral("trim"));
        return QString();
    }
    TrimOptions options;
    options.trim.rule = StaticRule::AlternatingBorder;
    if (auto e = takeSources(parser.positionalArguments(), QStringLiteral("trim"), options.sources))
        return *e;
    if (!parser.isSet("output"))
        return QStringLiteral("trim needs an output mesh: -o out.obj (%1)")
            .arg(QString::fromStdString(meshExportFormatsText()));
    options.output = parser.value("output");
    if (!isMeshExportPath(options.output.toStdString()))
        return QStringLiteral("-o %1: unknown mesh format (use %2)")
            .arg(options.output, QString::fromStdString(meshExportFormatsText()));
    if (auto e = checkOutputPaths({{"-o", options.output}}))
        return *e;
    options.ruleGiven = parser.isSet("rule");
    if (options.ruleGiven) {
        if (parser.value("rule") == QLatin1String("none"))
            return QStringLiteral("--rule none keeps no solid; choose a rule (%1)")
                .arg(QString::fromStdString(staticRuleNamesHelp()));
        if (auto e = parseRuleOption(parser.value("rule"), options.trim))
            return *e;
    }
    options.csgGiven = parser.isSet("csg");
    if (options.csgGiven)
        if (auto e = parseCsgOption(parser.value("csg"), options.trim.csg))
            return *e;
    for (const QString& text : parser.values("object-rule"))
        if (auto e = parseObjectRuleOption(text, options.trim.csg))
            return *e;
    for (const QString& text : parser.values("object-transform"))
        if (auto e = parseObjectTransform(text, options.transforms))
            return *e;
    if (auto e = parseParameter(parser, hole_closing_parameters::kCloseHoles, options.closeHoles))
        return *e;
    if (auto e = parseClipOptions(parser, options.trim))
        return *e;
    if (auto e = parsePoseOptions(parser, options))
        return *e;
    return options;
}

// A scene project's rule, CSG and object rules where the command line gave none.
void adoptSaved(const LoadedScene& loaded, TrimOptions& options)
{
    if (!options.ruleGiven && loaded.savedRule)
        options.trim.rule = *loaded.savedRule;
    adoptSavedCsg(loaded, options.trim.csg, options.csgGiven, true);
}

QString classificationText(const TrimSettings& trim)
{
    QString text = QString::fromStdString(ruleName(trim.rule));
    if (trim.csg.enabled())
        text += QStringLiteral(", CSG %1").arg(QString::fromStdString(formatCsgExpression(trim.csg.expression)));
    const int planes = trim.clipSet().enabledCount();
    if (planes > 0)
        text += planes == 1 ? QStringLiteral(", cut by 1 clipping plane")
                            : QStringLiteral(", cut by %1 clipping planes").arg(planes);
    return text;
}

QString solidLine(const QString& what, const QString& output, const TrimmedSolid& solid)
{
    const TrimmedSolidStats& s = solid.stats;
    return QStringLiteral("%1 -> %2: %3 triangles, %4 vertices, %5; volume %6")
        .arg(what, output)
        .arg(solid.mesh.triangles.size())
        .arg(solid.mesh.positions.size())
        .arg(s.openEdges == 0 ? QStringLiteral("closed") : QStringLiteral("%1 open edges").arg(s.openEdges))
        .arg(s.signedVolume, 0, 'g', 8);
}

int exportTrimmedSolid(TrimOptions options)
{
    LoadedScene loaded = loadScenes(options.sources);
    if (options.closeHoles)
        closeHolesNoted(loaded);
    std::optional<QString> error = applyObjectTransforms(options.transforms, loaded.scene);
    adoptSaved(loaded, options);
    if (!error)
        error = checkObjectIds(options.trim.csg, loaded.scene.objects.size());
    if (error) {
        printError(*error);
        return 2;
    }
    if (!loaded.trimmable()) {
        printError(QStringLiteral("%1 has no inside to export: %2")
                       .arg(QString::fromStdString(loaded.displayName),
                            QString::fromStdString(loaded.trimUnavailableReason())));
        return 1;
    }
    const TrimmedSolid solid = cutTrimmedSolid(loaded.scene, options.trim, terminalProgress());
    const TrimmedSolidStats& s = solid.stats;
    const std::string comment = loaded.displayName + " trimmed by " + classificationText(options.trim).toStdString();
    saveTriangleMesh(options.output.toStdString(), solid.mesh, comment);
    printLine(solidLine(
        QStringLiteral("%1: %2").arg(QString::fromStdString(loaded.displayName), classificationText(options.trim)),
        options.output, solid));
    printLine(QStringLiteral("arrangement: %1 input triangles (%2 degenerate dropped) refined into %3 faces (%4 "
                             "cancelled), %5 connected pieces; refine %6 ms, windings %7 ms")
                  .arg(s.inputTriangles)
                  .arg(s.degenerateTriangles)
                  .arg(s.refinedFaces)
                  .arg(s.cancelledFaces)
                  .arg(s.components)
                  .arg(s.refineMs, 0, 'f', 0)
                  .arg(s.windingMs, 0, 'f', 0));
    if (s.roundingMergedVertices > 0)
        printNote(QStringLiteral("rounding to float put %1 exact vertices on a neighbour's position and dropped the "
                                 "%2 faces that collapsed with them")
                      .arg(s.roundingMergedVertices)
                      .arg(s.roundingDroppedFaces));
    if (s.nonManifoldEdges > 0)
        printNote(QStringLiteral("%1 edges where kept cells touch along an edge (more than two faces meet): the "
                                 "solid is closed but not manifold there")
                      .arg(s.nonManifoldEdges));
    if (s.contradictions > 0)
        printNote(QStringLiteral("%1 faces with inconsistent winding numbers (the input is not a closed surface "
                                 "everywhere)")
                      .arg(s.contradictions));
    return 0;
}

// --pose / --poses: each pose of the animation trimmed on its own, written as it is done
// (one file per pose), or gathered into one glTF that plays them.
int exportTrimmedPoses(const TrimOptions& options)
{
    const std::string& source = options.sources.front();
    AnimationLoadOptions load;
    load.closeHoles = options.closeHoles;
    HoleClosing closing;
    const MeshAnimation animation = loadAnimation(source, load, {}, &closing);
    const std::string name = std::filesystem::path(source).filename().string();
    if (options.closeHoles)
        noteHolesClosed(name, closing);
    const PoseSelection& selection = *options.poses;
    if (std::size_t(selection.last) >= animation.poseCount()) {
        printError(QStringLiteral("%1 has %2 poses (0 to %3); pose %4 does not exist")
                       .arg(QString::fromStdString(source))
                       .arg(animation.poseCount())
                       .arg(animation.poseCount() - 1)
                       .arg(selection.last));
        return 2;
    }
    const bool oneFile = !selection.sequence || !hasPoseNumber(options.output);
    const QString classification = classificationText(options.trim);
    std::vector<SequenceMesh> gathered;
    double totalVolume = 0.0;
    try {
        trimAnimationPoses(
            animation, std::size_t(selection.first), std::size_t(selection.last), options.trim,
            [&](std::size_t pose, const TrimmedSolid& solid) {
                const std::string what = name + " pose " + std::to_string(pose);
                totalVolume += solid.stats.signedVolume;
                if (oneFile && selection.sequence) {
                    printLine(solidLine(QString::fromStdString(what), options.output, solid));
                    gathered.push_back({trimmedPoseName(pose), solid.mesh});
                    return;
                }
                const QString path = selection.sequence ? posePath(options.output, int(pose)) : options.output;
                saveTriangleMesh(path.toStdString(), solid.mesh, what + " trimmed by " + classification.toStdString());
                printLine(solidLine(QString::fromStdString(what), path, solid));
            },
            terminalProgress());
    } catch (const std::invalid_argument& e) {
        printError(QStringLiteral("%1: %2").arg(QString::fromStdString(source), QString::fromUtf8(e.what())));
        return 1;
    }
    if (oneFile && selection.sequence) {
        saveMeshSequenceGltf(options.output.toStdString(), gathered, 1.0 / options.fps,
                             name + " trimmed by " + classification.toStdString());
        printLine(QStringLiteral("wrote %1: %2 poses, one node each, shown in turn at %3 fps")
                      .arg(options.output)
                      .arg(gathered.size())
                      .arg(options.fps));
    }
    printLine(QStringLiteral("%1 poses trimmed by %2; total volume %3")
                  .arg(selection.last - selection.first + 1)
                  .arg(classification)
                  .arg(totalVolume, 0, 'g', 8));
    return 0;
}

} // namespace

int runTrimVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QString help;
    auto parsed = parseTrimOptions(arguments, &help);
    if (const std::optional<int> exitCode = exitIfNotParsed(parsed, help))
        return *exitCode;
    const TrimOptions& options = std::get<TrimOptions>(parsed);
    return runGuarded([&] { return options.poses ? exportTrimmedPoses(options) : exportTrimmedSolid(options); },
                      options.sources);
}

} // namespace trimlab::app
