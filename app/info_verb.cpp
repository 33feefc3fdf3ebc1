#include "app/info_verb.h"

#include "app/cli_messages.h"

#include "core/catalog/scene_source.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace trimlab::app {

namespace {

int printReports(const std::string& source)
{
    const LoadedScene loaded = loadScene(source);
    for (std::size_t i = 0; i < loaded.reports.size(); ++i)
        printLine(QString::fromStdString(formatReport(loaded.reports[i], loaded.scene.objects[i].name)));
    return 0;
}

} // namespace

int runInfoVerb(int argc, char** argv, const QStringList& arguments)
{
    QCoreApplication application(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription("Prints the validation report of a mesh file or demo scene.");
    parser.addPositionalArgument("source", "A mesh file (.obj .ply .stl .off .gltf .glb, optionally .gz) or demo:NAME.");
    parser.addHelpOption();
    if (!parser.parse(QStringList{QStringLiteral("trimlab info")} + arguments)) {
        printError(parser.errorText());
        return 2;
    }
    if (parser.isSet("help")) {
        printLine(verbHelpText(parser, QStringLiteral("info")));
        return 0;
    }
    if (parser.positionalArguments().size() != 1) {
        printError("info needs exactly one source (a mesh file or demo:NAME); see trimlab info --help");
        return 2;
    }
    const std::string source = parser.positionalArguments().first().toStdString();
    return runGuarded([&] { return printReports(source); });
}

} // namespace trimlab::app
