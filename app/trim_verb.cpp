#include "app/trim_verb.h"

#include "app/cli_messages.h"
#include "app/output_paths.h"
#include "app/parameter_options.h"
#include "app/scene_composition.h"
#include "app/terminal_progress.h"

#include "core/catalog/scene_source.h"
#include "core/mesh/mesh_export.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/clip_set.h"
#include "core/trim/csg_expression.h"
#include "core/trim/hole_closing.h"
#include "core/trim/static_rule.h"

#include <QCommandLineParser>
#include <QCoreApplication>

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
         QStringLiteral("The mesh to write: %1.").arg(QString::fromStdString(meshExportFormatsText())),
         "file"},
    });
    parser.addOption(commandLineOption(hole_closing_parameters::kCloseHoles));
    parser.addHelpOption();
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
    printLine(QStringLiteral("%1: %2 -> %3: %4 triangles, %5 vertices, %6; volume %7")
                  .arg(QString::fromStdString(loaded.displayName), classificationText(options.trim), options.output)
                  .arg(solid.mesh.triangles.size())
                  .arg(solid.mesh.positions.size())
                  .arg(s.openEdges == 0 ? QStringLiteral("closed") : QStringLiteral("%1 open edges").arg(s.openEdges))
                  .arg(s.signedVolume, 0, 'g', 8));
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

} // namespace

int runTrimVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QString help;
    auto parsed = parseTrimOptions(arguments, &help);
    if (const std::optional<int> exitCode = exitIfNotParsed(parsed, help))
        return *exitCode;
    const TrimOptions& options = std::get<TrimOptions>(parsed);
    return runGuarded([&] { return exportTrimmedSolid(options); }, options.sources);
}

} // namespace trimlab::app
