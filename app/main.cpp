// trimlab: the GUI (optionally opening a file or demo) or a batch verb.
//   trimlab [FILE|demo:NAME]
//   trimlab render SOURCE [options] -o out.png
//   trimlab info SOURCE
#include "cli_messages.h"
#include "gui_launcher.h"
#include "info_verb.h"
#include "render_verb.h"

#include <QStringList>

#include <cstring>

namespace {

QStringList argumentsAfterVerb(int argc, char** argv)
{
    QStringList arguments;
    for (int i = 2; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    return arguments;
}

void printUsage()
{
    trimlab::app::printLine(
        "Usage:\n"
        "  trimlab [FILE|demo:NAME]          open the GUI (default: demo:pushed-sphere)\n"
        "  trimlab render SOURCE -o out.png  render an image (see trimlab render --help)\n"
        "  trimlab info SOURCE               print the mesh validation report\n"
        "SOURCE is a mesh file (.obj .ply .stl .off .gltf .glb, optionally .gz) or a built-in demo:\n"
        "  demo:pushed-sphere, demo:crossing-loop, demo:nested-spheres, demo:sphere");
}

} // namespace

int main(int argc, char** argv)
{
    const char* verb = argc > 1 ? argv[1] : "";
    if (std::strcmp(verb, "render") == 0)
        return trimlab::app::runRenderVerb(argc, argv, argumentsAfterVerb(argc, argv));
    if (std::strcmp(verb, "info") == 0)
        return trimlab::app::runInfoVerb(argc, argv, argumentsAfterVerb(argc, argv));
    if (std::strcmp(verb, "--help") == 0 || std::strcmp(verb, "-h") == 0) {
        printUsage();
        return 0;
    }
    return trimlab::app::runGui(argc, argv);
}
