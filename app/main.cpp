// trimlab: the GUI (optionally opening a file or demo) or a batch verb.
//   trimlab [FILE|demo:NAME]
//   trimlab render SOURCE [options] -o out.png
//   trimlab info SOURCE
//   trimlab bench [--scenes a,b] [--methods a,b] [--size WxH] [--json out.json]
//   trimlab segment ANIMATION --clusters N --h H -o labels.json
//   trimlab skin ANIMATION --bones B --method lbs|dqs -o out.glb
//   trimlab skeleton MESH [--nodes N] -o rig.glb --json skeleton.json
#include "bench_verb.h"
#include "cli_messages.h"
#include "gui_launcher.h"
#include "info_verb.h"
#include "render_verb.h"
#include "segment_verb.h"
#include "skeleton_verb.h"
#include "skin_verb.h"

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
        "  trimlab bench [options]           time every multi-fragment method (see trimlab bench --help)\n"
        "  trimlab segment ANIMATION [options] -o labels.json\n"
        "                                    segment a mesh animation (see trimlab segment --help)\n"
        "  trimlab skin ANIMATION --bones B --method lbs|dqs -o out.glb\n"
        "                                    skin a mesh animation, export glTF (see trimlab skin --help)\n"
        "  trimlab skeleton MESH [--nodes N] [-o rig.glb] [--json skeleton.json]\n"
        "                                    extract a skeleton and skinning weights, export a rigged glTF\n"
        "                                    (see trimlab skeleton --help)\n"
        "SOURCE is a mesh file (.obj .ply .stl .off .gltf .glb, optionally .gz) or a built-in demo:\n"
        "  demo:pushed-sphere, demo:crossing-loop, demo:nested-spheres, demo:sphere");
}

struct BatchVerb {
    const char* name;
    int (*run)(int argc, char** argv, const QStringList& arguments);
};

// Each verb creates the Qt application object it needs (a GUI one only where OpenGL is).
constexpr BatchVerb kVerbs[] = {
    {"render", trimlab::app::runRenderVerb},
    {"info", trimlab::app::runInfoVerb},
    {"bench", trimlab::app::runBenchVerb},
    {"segment", trimlab::app::runSegmentVerb},
    {"skin", trimlab::app::runSkinVerb},
    {"skeleton", trimlab::app::runSkeletonVerb},
};

} // namespace

int main(int argc, char** argv)
{
    const char* verb = argc > 1 ? argv[1] : "";
    for (const BatchVerb& batch : kVerbs)
        if (std::strcmp(verb, batch.name) == 0)
            return batch.run(argc, argv, argumentsAfterVerb(argc, argv));
    if (std::strcmp(verb, "--help") == 0 || std::strcmp(verb, "-h") == 0) {
        printUsage();
        return 0;
    }
    return trimlab::app::runGui(argc, argv);
}
