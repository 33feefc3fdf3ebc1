// The exact export against the libraries people pick for booleans, as whole processes
// side by side in one run: `trimlab trim`, Manifold's WebAssembly build (npm
// manifold-3d, run with node) and Blender's Exact boolean (Debian's blender), each
// reading the same plain OBJ files and writing its result. Not a test: it never fails on
// a number and is not registered with CTest. Run by hand:
//   npm install --prefix build/exact-peers manifold-3d@3.5.4
//   build/tests/core/solid/bench_exact --manifold build/exact-peers
//   build/tests/core/solid/bench_exact --profile          (the stages, in this process)
// Cases: the six EMBER pairs of ../shared/data/booleans (A minus B, `--rule nonzero
// --csg "0 - 1"`) and every closed mesh of ../shared/data/selfintersect (trimmed by
// `nonzero`: what Blender's exact self-union keeps; Manifold does not resolve
// self-crossing input, so it has no column there). Names given on the command line
// pick cases by substring. The three programs alternate (the starting one rotates every
// round); each time is the median of --repeat rounds, and the table prints the peer's
// time over TrimLab's (above 1: TrimLab is faster) and the relative volume difference.
// --profile instead runs the export in this process and prints where its time goes
// (core/solid/exact_profile.h), which docs/trimmed-solid.md quotes.
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_validation.h"
#include "core/solid/trimmed_solid.h"
#include "core/trim/csg_expression.h"
#include "run_trimlab.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace trimlab;

struct BenchCase {
    QString name;
    QStringList sources; ///< one (a self-crossing mesh) or two (A minus B)
    std::size_t triangles = 0;
    QStringList plainObj; ///< the sources as plain OBJ in the temporary folder
};

struct ToolRun {
    std::vector<double> seconds;
    std::optional<double> volume;
    QString failure; ///< why it gave no result, when it did not
};

std::vector<BenchCase> collectCases(const QString& data, const QStringList& filters)
{
    std::vector<BenchCase> cases;
    const QDir booleans(data + QStringLiteral("/booleans"));
    for (const QString& a : booleans.entryList({QStringLiteral("ember-*_A.obj.gz")}, QDir::Files, QDir::Name)) {
        const QString name = a.left(a.indexOf(QLatin1String("_A")));
        cases.push_back({name, {booleans.filePath(a), booleans.filePath(name + QStringLiteral("_B.obj.gz"))}, 0, {}});
    }
    const QDir self(data + QStringLiteral("/selfintersect"));
    for (const QString& file : self.entryList(QDir::Files, QDir::Name))
        cases.push_back({file.left(file.indexOf(QLatin1Char('.'))), {self.filePath(file)}, 0, {}});
    if (filters.isEmpty())
        return cases;
    std::vector<BenchCase> picked;
    for (const BenchCase& c : cases)
        if (std::any_of(filters.begin(), filters.end(), [&](const QString& f) { return c.name.contains(f); }))
            picked.push_back(c);
    return picked;
}

// Writes the case's meshes as plain OBJ (what every program reads); false, with a line
// printed, for a mesh that is not closed (it has no inside to trim).
bool prepare(BenchCase& c, const QDir& folder)
{
    for (int k = 0; k < c.sources.size(); ++k) {
        const TriangleMesh mesh = loadMesh(c.sources[k].toStdString());
        if (!validateMesh(mesh).closed()) {
            std::printf("%s: skipped, not closed\n", qPrintable(c.name));
            return false;
        }
        c.triangles += mesh.triangles.size();
        const QString path = folder.filePath(QStringLiteral("%1_%2.obj").arg(c.name).arg(k));
        saveTriangleMesh(path.toStdString(), mesh);
        c.plainObj << path;
    }
    return true;
}

// Runs one program, returning its wall time and the volume it printed after `marker`.
void timeProcess(const QString& program, const QStringList& arguments, const QString& marker, ToolRun& run)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    QElapsedTimer clock;
    clock.start();
    process.start(program, arguments);
    const bool finished = process.waitForFinished(30 * 60 * 1000);
    const double seconds = double(clock.nsecsElapsed()) * 1e-9;
    const QString out = QString::fromLocal8Bit(process.readAll());
    const QRegularExpressionMatch volume =
        QRegularExpression(QRegularExpression::escape(marker) + QStringLiteral("\\s*([-+0-9.eE]+)")).match(out);
    if (!finished || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0 || !volume.hasMatch()) {
        const QStringList lines = out.trimmed().split(QLatin1Char('\n'));
        run.failure = lines.isEmpty() ? QStringLiteral("no output") : lines.last().left(60);
        return;
    }
    run.seconds.push_back(seconds);
    run.volume = volume.captured(1).toDouble();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.empty() ? NAN : values[values.size() / 2];
}

QString timeCell(const ToolRun& run)
{
    return run.seconds.empty() ? QStringLiteral("— (%1)").arg(run.failure)
                               : QString::number(median(run.seconds), 'f', 2) + QStringLiteral(" s");
}

QString ratioCell(const ToolRun& peer, const ToolRun& ours)
{
    if (peer.seconds.empty() || ours.seconds.empty())
        return QStringLiteral("—");
    return QString::number(median(peer.seconds) / median(ours.seconds), 'f', 2) + QStringLiteral("×");
}

QString agreementCell(const ToolRun& peer, const ToolRun& ours)
{
    if (!peer.volume || !ours.volume)
        return QStringLiteral("—");
    return QString::number(std::abs(*peer.volume - *ours.volume) / std::abs(*ours.volume), 'e', 1);
}

struct Peers {
    QString trimlab;
    QString manifoldModules; ///< empty: not run
    QString blender;         ///< empty: not run
    QString scripts;
};

void benchCase(const BenchCase& c, const Peers& peers, int repeat, const QDir& folder)
{
    const bool boolean = c.plainObj.size() == 2;
    const QString out = folder.filePath(c.name + QStringLiteral("_out.obj"));
    ToolRun ours, manifold, blender;
    QStringList trimArguments{QStringLiteral("trim")};
    trimArguments << c.plainObj << QStringLiteral("--rule") << QStringLiteral("nonzero");
    if (boolean)
        trimArguments << QStringLiteral("--csg") << QStringLiteral("0 - 1");
    trimArguments << QStringLiteral("-o") << out;
    const auto runOurs = [&] { timeProcess(peers.trimlab, trimArguments, QStringLiteral("volume"), ours); };
    const auto runManifold = [&] {
        if (peers.manifoldModules.isEmpty())
            manifold.failure = QStringLiteral("--manifold not given");
        else if (!boolean)
            manifold.failure = QStringLiteral("refuses self-crossing input");
        else
            timeProcess(
                QStringLiteral("node"),
                QStringList{peers.scripts + QStringLiteral("/manifold_difference.mjs"), peers.manifoldModules, out}
                    << c.plainObj,
                QStringLiteral("manifold volume"), manifold);
    };
    const auto runBlender = [&] {
        if (peers.blender.isEmpty()) {
            blender.failure = QStringLiteral("not installed");
            return;
        }
        timeProcess(peers.blender,
                    QStringList{QStringLiteral("-b"), QStringLiteral("--factory-startup"), QStringLiteral("--python"),
                                peers.scripts + QStringLiteral("/blender_exact.py"), QStringLiteral("--"), out}
                        << c.plainObj,
                    QStringLiteral("blender volume"), blender);
    };
    const std::vector<std::function<void()>> order{runOurs, runManifold, runBlender};
    for (int round = 0; round < repeat; ++round)
        for (std::size_t k = 0; k < order.size(); ++k)
            order[(k + std::size_t(round)) % order.size()]();
    std::printf("| %s | %zu | %s | %s | %s | %s | %s | %.10g | %s | %s |\n", qPrintable(c.name), c.triangles,
                qPrintable(timeCell(ours)), qPrintable(timeCell(manifold)), qPrintable(ratioCell(manifold, ours)),
                qPrintable(timeCell(blender)), qPrintable(ratioCell(blender, ours)), ours.volume.value_or(NAN),
                qPrintable(agreementCell(manifold, ours)), qPrintable(agreementCell(blender, ours)));
    std::fflush(stdout);
}

// The export in this process, stage by stage (exact_profile.h).
void profileCase(const BenchCase& c)
{
    Scene scene;
    for (const QString& source : c.sources)
        scene.objects.push_back({QFileInfo(source).fileName().toStdString(), loadMesh(source.toStdString())});
    TrimSettings settings;
    settings.rule = StaticRule::Nonzero;
    if (c.sources.size() == 2)
        settings.csg.expression = *parseCsgExpression("0 - 1", nullptr);
    const TrimmedSolid solid = trimmedSolid(scene, settings);
    const ExactProfile& p = solid.stats.profile;
    std::printf("| %s | %zu | %zu | %zu | %zu | %zu | %.0f | %.0f | %.0f | %.0f | %zu | %.0f | %.0f | %.0f | %.0f |\n",
                qPrintable(c.name), solid.stats.inputTriangles, p.candidatePairs, p.constructedPairs, p.splitTriangles,
                p.largestCoplanarGroup, p.pairsMs, p.constructMs, p.triangulateMs, p.mergeMs, p.sortedEdges, p.wedgesMs,
                p.walkMs, p.raysMs, solid.stats.refineMs + solid.stats.windingMs);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addHelpOption();
    parser.addOption({QStringLiteral("repeat"), QStringLiteral("Rounds per case (median)."), QStringLiteral("n"),
                      QStringLiteral("3")});
    parser.addOption({QStringLiteral("data"), QStringLiteral("The shared data folder."), QStringLiteral("dir"),
                      QStringLiteral(TRIMLAB_SHARED_DATA_DIR)});
    parser.addOption({QStringLiteral("manifold"),
                      QStringLiteral("Folder where `npm install --prefix` put manifold-3d (no Manifold column "
                                     "without it)."),
                      QStringLiteral("dir")});
    parser.addOption({QStringLiteral("blender"), QStringLiteral("Blender to run, or none."), QStringLiteral("path"),
                      QStringLiteral("blender")});
    parser.addOption({QStringLiteral("profile"), QStringLiteral("Print the export's stages instead (in process).")});
    parser.addPositionalArgument(QStringLiteral("names"), QStringLiteral("Cases whose names contain one of these."));
    parser.process(app);
    try {
        std::vector<BenchCase> cases = collectCases(parser.value(QStringLiteral("data")), parser.positionalArguments());
        if (parser.isSet(QStringLiteral("profile"))) {
            std::printf("| case | triangles | candidate pairs | constructed | split triangles | largest coplanar group "
                        "| pairs ms | construct ms | triangulate ms | merge ms | sorted edges | wedges ms | "
                        "walk ms | rays ms | export ms |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
                        "---:|---:|---:|---:|\n");
            for (const BenchCase& c : cases)
                if (c.sources.size() == 2 || validateMesh(loadMesh(c.sources.front().toStdString())).closed())
                    profileCase(c);
            return 0;
        }
        QTemporaryDir folder;
        Peers peers{test::trimlabExecutable(),
                    parser.value(QStringLiteral("manifold")),
                    {},
                    QStringLiteral(TRIMLAB_EXACT_PEERS_DIR)};
        const QString blender = parser.value(QStringLiteral("blender"));
        if (blender != QLatin1String("none"))
            peers.blender = QStandardPaths::findExecutable(blender);
        const int repeat = std::max(1, parser.value(QStringLiteral("repeat")).toInt());
        std::printf("%d rounds per case, median wall time of the whole process (load, boolean, write)\n\n", repeat);
        std::printf(
            "| case | triangles | TrimLab | Manifold | Manifold ÷ TrimLab | Blender Exact | Blender ÷ TrimLab | "
            "TrimLab volume | Δ Manifold | Δ Blender |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (BenchCase& c : cases)
            if (prepare(c, QDir(folder.path())))
                benchCase(c, peers, repeat, QDir(folder.path()));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_exact: %s\n", e.what());
        return 1;
    }
    return 0;
}
