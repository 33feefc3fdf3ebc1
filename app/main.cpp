// trimlab: the GUI (optionally opening a file or demo) or a batch verb.
//   trimlab [FILE|demo:NAME]
//   trimlab render SOURCE... [options] -o out.png
//   trimlab info SOURCE...
//   trimlab bench [--scenes a,b] [--methods a,b] [--size WxH] [--json out.json]
//   trimlab segment ANIMATION --clusters N --h H -o labels.json
//   trimlab skin ANIMATION --bones B [--method rigid|lbs|dqs] -o out.glb
//   trimlab skeleton MESH [--nodes N] -o rig.glb --json skeleton.json
//   trimlab trim SOURCE... --rule R [--csg EXPR] -o out.obj|.ply|.stl|.gltf|.glb
#include "app/bench_verb.h"
#include "app/cli_messages.h"
#include "app/gui_launcher.h"
#include "app/info_verb.h"
#include "app/render_verb.h"
#include "app/segment_verb.h"
#include "app/skeleton_verb.h"
#include "app/skin_verb.h"
#include "app/trim_verb.h"

#include "core/catalog/scene_source.h"
#include "core/skinning/skinning_parameters.h"

#include <QString>
#include <QStringList>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <malloc.h>
#include <sys/resource.h>

namespace {

QStringList argumentsAfterVerb(int argc, char** argv)
{
    QStringList arguments;
    for (int i = 2; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    return arguments;
}

// "a|b|c": the choices of a parameter, as a usage line shows them.
QString choiceAlternatives(const trimlab::ParameterSpec& spec)
{
    QStringList names;
    for (const trimlab::ChoiceValue& choice : spec.choices)
        if (choice.commandLine)
            names << QString::fromUtf8(choice.name.data(), qsizetype(choice.name.size()));
    return names.join(QLatin1Char('|'));
}

void printUsage()
{
    // The skin line's methods come from the skinning table: the fit is optional (rigid
    // by default), and a new method appears here without editing this text.
    const QString skinLine = QStringLiteral("  trimlab skin ANIMATION --bones B [--method %1] -o out.glb\n")
                                 .arg(choiceAlternatives(trimlab::skinning_parameters::kFit));
    trimlab::app::printLine(
        QStringLiteral(
            "Usage:\n"
            "  trimlab [FILE|demo:NAME]          open the GUI (default: demo:pushed-sphere)\n"
            "  trimlab render SOURCE... -o out.png\n"
            "                                    render an image (see trimlab render --help)\n"
            "  trimlab info SOURCE...            print the mesh validation report\n"
            "  trimlab trim SOURCE... --rule R -o out.obj\n"
            "                                    export the trimmed solid as a closed mesh (see trimlab trim --help)\n"
            "  trimlab bench [options]           time every multi-fragment method (see trimlab bench --help)\n"
            "  trimlab segment ANIMATION [options] -o labels.json\n"
            "                                    segment a mesh animation (see trimlab segment --help)\n") +
        skinLine +
        QStringLiteral(
            "                                    skin a mesh animation, export glTF (see trimlab skin --help)\n"
            "  trimlab skeleton MESH [--nodes N] [-o rig.glb] [--json skeleton.json]\n"
            "                                    extract a skeleton and skinning weights, export a rigged glTF\n"
            "                                    (see trimlab skeleton --help)\n"
            "SOURCE is a mesh file (.obj .ply .stl .off .gltf .glb, optionally .gz), a NURBS file\n"
            "(.nurbs.json), a .trimlab project (render) or a built-in demo:"));
    // The demos come from the scene registry, so a new demo is listed without editing this.
    for (const trimlab::DemoEntry& demo : trimlab::builtInDemos())
        trimlab::app::printLine(
            QStringLiteral("  %1  %2")
                .arg(QString::fromStdString(demo.source).leftJustified(26))
                .arg(QString::fromUtf8(demo.description.data(), qsizetype(demo.description.size()))));
}

struct BatchVerb {
    const char* name;
    int (*run)(int argc, char** argv, const QStringList& arguments);
};

// Each verb creates the Qt application object it needs (a GUI one only where OpenGL is).
constexpr BatchVerb kVerbs[] = {
    {"render", trimlab::app::runRenderVerb}, {"info", trimlab::app::runInfoVerb},
    {"bench", trimlab::app::runBenchVerb},   {"segment", trimlab::app::runSegmentVerb},
    {"skin", trimlab::app::runSkinVerb},     {"skeleton", trimlab::app::runSkeletonVerb},
    {"trim", trimlab::app::runTrimVerb},
};

// Under an address-space limit (prlimit --as, ulimit -v) glibc cannot reserve the 64 MiB
// a thread's own malloc arena takes, and then serves every allocation of that thread with
// a separate mmap: a skinning fit under 300 MB ran for minutes instead of seconds. One
// shared arena grows within the limit and fails cleanly at its end.
void shareOneMallocArenaUnderAddressLimit()
{
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        ::mallopt(M_ARENA_MAX, 1);
}

// A finished verb leaves at once: its outputs are complete and synced, its Qt application
// is gone, and nothing is left to clean up. Running the libraries' exit handlers instead
// can keep it waiting for ever: OpenBLAS's joins a worker thread that spins on a buffer an
// address-space limit (prlimit --as) refused, after the verb had printed its error.
[[noreturn]] void endBatchVerb(int exitCode)
{
    std::fflush(nullptr);
    std::_Exit(exitCode);
}

} // namespace

int main(int argc, char** argv)
{
    // A file-size limit (ulimit -f, a batch farm's quota) then fails the write with EFBIG,
    // which every save reports in one line with the old file kept, instead of the kernel
    // ending the process halfway with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    shareOneMallocArenaUnderAddressLimit();
    const char* verb = argc > 1 ? argv[1] : "";
    for (const BatchVerb& batch : kVerbs)
        if (std::strcmp(verb, batch.name) == 0)
            endBatchVerb(batch.run(argc, argv, argumentsAfterVerb(argc, argv)));
    if (std::strcmp(verb, "--help") == 0 || std::strcmp(verb, "-h") == 0) {
        printUsage();
        return 0;
    }
    return trimlab::app::runGui(argc, argv);
}
