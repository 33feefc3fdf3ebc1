#include "app/info_verb.h"

#include "app/cli_messages.h"
#include "app/parameter_options.h"
#include "app/scene_composition.h"

#include "core/catalog/scene_source.h"
#include "core/trim/csg_expression.h"
#include "core/trim/hole_closing.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace trimlab::app {

namespace {

QString pointText(const glm::dvec3& p)
{
    return QStringLiteral("(%1, %2, %3)").arg(p.x, 0, 'g', 6).arg(p.y, 0, 'g', 6).arg(p.z, 0, 'g', 6);
}

// One report per object, named by its id when the scene has several (the ids --csg,
// --object-rule and --object-transform use), then the scene's extent in world space; with
// --close-holes, of the objects closed.
int printReports(const std::vector<std::string>& sources, const std::vector<ObjectTransformOption>& transforms,
                 bool closeHoles)
{
    LoadedScene loaded = loadScenes(sources);
    if (closeHoles)
        closeHolesNoted(loaded);
    if (const std::optional<QString> error = applyObjectTransforms(transforms, loaded.scene)) {
        printError(*error);
        return 2;
    }
    const std::size_t count = loaded.scene.objects.size();
    for (std::size_t i = 0; i < loaded.reports.size(); ++i) {
        const std::string& name = loaded.scene.objects[i].name;
        printLine(QString::fromStdString(
            formatReport(loaded.reports[i], count > 1 ? "object " + std::to_string(i) + ": " + name : name)));
    }
    if (count > 1 || !transforms.empty()) {
        const Bounds world = loaded.scene.worldBounds();
        printLine(QStringLiteral("scene: %1 object(s), %2 triangles, world bounding box %3 - %4, trim modes %5")
                      .arg(count)
                      .arg(loaded.scene.triangleCount())
                      .arg(pointText(world.min), pointText(world.max),
                           loaded.trimmable() ? QStringLiteral("available")
                                              : QStringLiteral("unavailable (%1)")
                                                    .arg(QString::fromStdString(loaded.trimUnavailableReason()))));
    }
    if (loaded.savedCsg.enabled())
        printLine(QStringLiteral("saved CSG: %1")
                      .arg(QString::fromStdString(formatCsgExpression(loaded.savedCsg.expression))));
    return 0;
}

} // namespace

int runInfoVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Prints the validation report of each object of mesh files or demo scenes (several "
        "sources make one scene, object ids counting across them in order).");
    parser.addPositionalArgument("sources", "Mesh files (.obj .ply .stl .off .gltf .glb, optionally .gz) or demo:NAME.",
                                 "SOURCE...");
    parser.addOption({"object-transform", objectTransformHelp(), "id=tx,ty,tz[,rx,ry,rz[,s]]"});
    parser.addOption(commandLineOption(hole_closing_parameters::kCloseHoles));
    parser.addHelpOption();
    if (!parser.parse(QStringList{QStringLiteral("trimlab info")} + arguments)) {
        printError(parser.errorText());
        return 2;
    }
    if (parser.isSet("help")) {
        printLine(verbHelpText(parser, QStringLiteral("info")));
        return 0;
    }
    std::vector<std::string> sources;
    std::vector<ObjectTransformOption> transforms;
    std::optional<QString> error = takeSources(parser.positionalArguments(), QStringLiteral("info"), sources);
    for (const QString& text : parser.values("object-transform"))
        if (!error)
            error = parseObjectTransform(text, transforms);
    bool closeHoles = false;
    if (!error)
        error = parseParameter(parser, hole_closing_parameters::kCloseHoles, closeHoles);
    if (error) {
        printError(*error);
        return 2;
    }
    return runGuarded([&] { return printReports(sources, transforms, closeHoles); }, sources);
}

} // namespace trimlab::app
