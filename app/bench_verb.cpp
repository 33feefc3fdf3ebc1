#include "app/bench_verb.h"

#include "app/bench_json.h"
#include "app/bench_options.h"
#include "app/bench_runner.h"
#include "app/bench_skinning.h"
#include "app/bench_table.h"
#include "app/cli_messages.h"
#include "app/display_available.h"

#include "render/gl/offscreen_gl_context.h"
#include "render/trim_renderer.h"

#include <QDateTime>
#include <QGuiApplication>

#include <thread>

namespace trimlab::app {

namespace {

BenchHeader makeHeader(const BenchOptions& options, const render::TrimRenderer& renderer)
{
    BenchHeader header;
    header.version = QStringLiteral(TRIMLAB_VERSION);
    header.openGl = renderer.capabilities().summary();
    header.cpuThreads = std::thread::hardware_concurrency();
    const QDateTime now = QDateTime::currentDateTime();
    header.date = now.toOffsetFromUtc(now.offsetFromUtc()).toString(Qt::ISODate);
    header.sizes = options.sizes;
    header.views = options.views;
    header.repeat = options.repeat;
    header.parameters = options.parameters;
    header.methods = options.methods;
    header.locks = options.locks == BenchLocks::Auto       ? QStringLiteral("auto")
                   : options.locks == BenchLocks::SpinLock ? QStringLiteral("spin")
                                                           : QStringLiteral("both");
    return header;
}

QStringList sceneNames(const BenchOptions& options)
{
    if (!options.scenes.isEmpty() || !options.sources.empty())
        return options.scenes;
    QStringList names;
    for (const std::string& name : benchSceneNames())
        names << QString::fromStdString(name);
    return names;
}

/// Loads and measures one scene; false when it could not be loaded (a missing catalog
/// file is a skip, not a failure). `load` returns the scene, or nullopt with the skip
/// reason.
template <typename Load>
bool measureScene(const QString& name, Load&& load, BenchRunner& runner, BenchReport& report)
{
    std::string skipReason;
    std::optional<BenchScene> scene;
    try {
        scene = load(&skipReason);
    } catch (const std::exception& e) {
        printError(QStringLiteral("%1: %2").arg(name, QString::fromUtf8(e.what())));
        report.skipped.push_back({name, QStringLiteral("could not be loaded: %1").arg(QString::fromUtf8(e.what()))});
        return false;
    }
    if (!scene) {
        printNote(QStringLiteral("skipping %1: %2").arg(name, QString::fromStdString(skipReason)));
        report.skipped.push_back({name, QString::fromStdString(skipReason)});
        return true;
    }
    if (!scene->settings.trimEnabled && !scene->loaded.trimmable())
        printNote(QStringLiteral("%1 renders untrimmed: %2")
                      .arg(name, QString::fromStdString(scene->loaded.trimUnavailableReason())));
    report.header.scenes << name;
    runner.measureScene(*scene, report);
    return true;
}

// An animation scene (bench_skinning.h): its table is printed after the methods' table.
bool measureSkinningScene(const QString& name, const std::filesystem::path& data, render::TrimRenderer& renderer,
                          const BenchOptions& options, std::vector<SkinningBenchRow>& rows, BenchReport& report)
{
    std::string skipReason;
    try {
        const std::optional<MeshAnimation> animation =
            loadSkinningBenchAnimation(name.toStdString(), data, &skipReason);
        if (!animation) {
            printNote(QStringLiteral("skipping %1: %2").arg(name, QString::fromStdString(skipReason)));
            report.skipped.push_back({name, QString::fromStdString(skipReason)});
            return true;
        }
        printNote(QStringLiteral("%1: fitting 4 skinned models and timing every pose").arg(name));
        for (SkinningBenchRow& row : measureSkinning(renderer, *animation, name, std::max(options.repeat, 1)))
            rows.push_back(std::move(row));
        return true;
    } catch (const std::exception& e) {
        printError(QStringLiteral("%1: %2").arg(name, QString::fromUtf8(e.what())));
        report.skipped.push_back({name, QStringLiteral("could not be measured: %1").arg(QString::fromUtf8(e.what()))});
        return false;
    }
}

int runBench(const BenchOptions& options)
{
    render::OffscreenGlContext gl;
    render::TrimRenderer renderer(gl.context());
    BenchReport report;
    report.header = makeHeader(options, renderer);
    for (const QString& line : benchHeaderLines(report.header))
        printLine(line);
    const std::filesystem::path data = options.dataDirectory.isEmpty()
                                           ? defaultBenchDataDirectory()
                                           : std::filesystem::path(options.dataDirectory.toStdString());
    BenchRunner runner(renderer, options);
    bool allLoaded = true;
    std::vector<SkinningBenchRow> skinning;
    for (const QString& name : sceneNames(options)) {
        if (isSkinningBenchScene(name.toStdString())) {
            allLoaded = measureSkinningScene(name, data, renderer, options, skinning, report) && allLoaded;
            continue;
        }
        allLoaded = measureScene(
                        name, [&](std::string* skip) { return loadBenchScene(name.toStdString(), data, skip); }, runner,
                        report) &&
                    allLoaded;
    }
    if (!options.sources.empty()) {
        QStringList sources;
        for (const std::string& source : options.sources)
            sources << QString::fromStdString(source);
        const auto compose = [&](std::string*) {
            return std::optional<BenchScene>(
                composeBenchScene(options.sources, options.objectTransforms, options.composedTrim));
        };
        allLoaded = measureScene(sources.join(QStringLiteral(" + ")), compose, runner, report) && allLoaded;
    }
    printLine(QString());
    if (!report.cells.empty())
        for (const QString& line : benchTableLines(report))
            printLine(line);
    for (const QString& line : skinningTableLines(skinning))
        printLine(line);
    if (!options.jsonOutput.isEmpty())
        writeBenchJson(report, options.jsonOutput);
    QStringList failures = benchFailureLines(report);
    for (const SkinningBenchRow& row : skinning)
        if (!(row.largestDeviation <= kSkinningDeviationLimit))
            failures << QStringLiteral("%1 %2 %3: GPU-skinned positions differ from the CPU's by %4 of the diagonal "
                                       "(more than %5)")
                            .arg(row.animation, row.method, row.chain)
                            .arg(row.largestDeviation, 0, 'e', 2)
                            .arg(kSkinningDeviationLimit, 0, 'e', 0);
    for (const QString& failure : failures)
        printError(failure);
    return failures.isEmpty() && allLoaded ? 0 : 1;
}

} // namespace

int runBenchVerb(int argc, char** argv, const QStringList& arguments)
{
    QString help;
    auto parsed = parseBenchOptions(arguments, &help);
    if (const std::optional<int> exitCode = exitIfNotParsed(parsed, help))
        return *exitCode;
    if (!displayAvailable()) {
        printError("bench needs OpenGL and therefore a display; run it under 'xvfb-run -a'");
        return 1;
    }
    QGuiApplication application(argc, argv);
    const BenchOptions& options = std::get<BenchOptions>(parsed);
    return runGuarded([&] { return runBench(options); });
}

} // namespace trimlab::app
