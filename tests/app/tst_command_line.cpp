// The trimlab executable as users and scripts call it: exit codes and one-line errors for
// bad arguments and files, the info report, and `render` with both backends producing
// images whose ids and depths agree with the in-process CPU reference.
#include "gl_test_context.h"
#include "ids_png.h"
#include "run_trimlab.h"
#include "test_paths.h"
#include "trim_comparison.h"

#include "core/io/pfm_image.h"
#include "render/mfr/fragment_method.h"
#include "core/catalog/scene_source.h"
#include "core/skinning/skinning_parameters.h"
#include "core/timeline/frame_chain.h"
#include "core/timeline/stroke_replay.h"
#include "core/timeline/stroke_script.h"
#include "core/trim/dynamic_reference_renderer.h"
#include "core/trim/reference_renderer.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QFile>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace trimlab;

using trimlab::test::decodeIdsPng;
using trimlab::test::idsOnly;
using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

QString data(const QString& relative)
{
    return QString::fromStdString(test::testDataPath(relative.toStdString()).string());
}

const QStringList kPushedSphereView = {"render", "demo:pushed-sphere", "--rule", "alternating-border",
                                       "--clip", "0,0,-1,0",           "--size", "256x192"};

} // namespace

class TestCommandLine : public QObject {
    Q_OBJECT
private slots:
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void badInputsExitWithOne_data();
    void badInputsExitWithOne();
    void infoPrintsTheValidationReport();
    void infoNumbersTheObjectsOfSeveralSources();
    void helpListsEveryBuiltInDemo();
    void helpShowsTheSkinMethodOptionalWithEveryChoice();
    void openMeshRendersUntrimmedByDefault();
    void referenceBackendMatchesInProcessReference();
    void kplusBackendAgreesWithReference();
    void everyMethodRendersAndReportsItsStatistics();
    void scriptReplayRendersTheDynamicRulesLikeTheReference();
    void projectWithoutFramesRendersItsBaseMesh();

private:
    QTemporaryDir m_dir;
};

void TestCommandLine::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no source") << QStringList{"render", "-o", "x.png"} << "at least one source";
    QTest::newRow("no output") << QStringList{"render", "demo:sphere"} << "-o out.png";
    QTest::newRow("bad size") << QStringList{"render", "demo:sphere", "--size", "10", "-o", "x.png"} << "--size";
    QTest::newRow("bad clip") << QStringList{"render", "demo:sphere", "--clip", "1,2", "-o", "x.png"} << "--clip";
    QTest::newRow("zero clip normal") << QStringList{"render", "demo:sphere", "--clip", "0,0,0,1", "-o", "x.png"}
                                      << "must not be zero";
    QTest::newRow("bad rule") << QStringList{"render", "demo:sphere", "--rule", "winding", "-o", "x.png"} << "--rule";
    QTest::newRow("threshold rule without K")
        << QStringList{"render", "demo:sphere", "--rule", "w>=0", "-o", "x.png"} << "unknown --rule 'w>=0'";
    QTest::newRow("bad k") << QStringList{"render", "demo:sphere", "--k", "0", "-o", "x.png"} << "--k";
    QTest::newRow("bad camera") << QStringList{"render", "demo:sphere", "--camera", "0,0,3", "-o", "x.png"}
                                << "--camera";
    QTest::newRow("bad method") << QStringList{"render", "demo:sphere", "--method", "z-buffer", "-o", "x.png"}
                                << "--method 'z-buffer'";
    QTest::newRow("bad shared counters") << QStringList{"render", "demo:sphere", "--shared-counters",
                                                        "0",      "-o",          "x.png"}
                                         << "--shared-counters";
    QTest::newRow("bad backend") << QStringList{"render", "demo:sphere", "--backend", "vulkan", "-o", "x.png"}
                                 << "--backend";
    QTest::newRow("unknown option") << QStringList{"render", "demo:sphere", "--frobnicate", "-o", "x.png"}
                                    << "frobnicate";
    QTest::newRow("info without source") << QStringList{"info"} << "at least one source";
    QTest::newRow("frame without a design") << QStringList{"render", "demo:sphere", "--frame", "1", "-o", "x.png"}
                                            << "--frame and --classification need --script";
    QTest::newRow("bad classification") << QStringList{"render",           "demo:sphere", "--script", "s.json",
                                                       "--classification", "winding",     "-o",       "x.png"}
                                        << "--classification 'winding'";
    QTest::newRow("dynamic rules without a base rule")
        << QStringList{"render", "demo:sphere", "--script", "s.json", "--rule", "none", "-o", "x.png"}
        << "--rule none cannot classify";
}

void TestCommandLine::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
}

void TestCommandLine::badInputsExitWithOne_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown demo") << QStringList{"render", "demo:teapot", "--backend", "reference", "-o", "x.png"}
                                  << "Unknown demo scene 'teapot'";
    QTest::newRow("missing file") << QStringList{"info", "/nonexistent/mesh.obj"} << "/nonexistent/mesh.obj";
    QTest::newRow("broken file") << QStringList{"info", data("broken/nan.obj")} << "nan.obj";
    QTest::newRow("missing stroke script")
        << QStringList{"render",    "demo:sphere", "--script", "/nonexistent/strokes.json",
                       "--backend", "reference",   "-o",       "x.png"}
        << "/nonexistent/strokes.json";
    QTest::newRow("frame beyond the last")
        << QStringList{"render",  "demo:sphere", "--script",  data("scripts/fig8_7_extended_tip.json"),
                       "--frame", "9",           "--backend", "reference",
                       "-o",      "x.png"}
        << "beyond the last frame";
    QTest::newRow("trim asked on an open mesh")
        << QStringList{"render", data("meshes/open_square.obj"), "--rule", "parity", "--backend", "reference", "-o",
                       "x.png"}
        << "unavailable";
}

void TestCommandLine::badInputsExitWithOne()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const Run run = runTrimlab(arguments);
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.startsWith("trimlab: error: ") && run.err.contains(message), qPrintable(run.err));
}

void TestCommandLine::infoPrintsTheValidationReport()
{
    Run run = runTrimlab({"info", data("meshes/cube.obj")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("trim modes: available"), qPrintable(run.out));
    run = runTrimlab({"info", data("meshes/open_square.obj")});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("trim modes: unavailable") && run.out.contains("boundary"), qPrintable(run.out));
}

// Several sources: one report per object, numbered as --csg counts them, and the scene's
// world extent after --object-transform (the unit cube [0,1]^3 doubled, moved 10 in x).
void TestCommandLine::infoNumbersTheObjectsOfSeveralSources()
{
    const Run run = runTrimlab(
        {"info", data("meshes/open_square.obj"), data("meshes/cube.obj"), "--object-transform", "1=10,0,0,0,0,0,2"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("object 0: open_square.obj") && run.out.contains("object 1: cube.obj"),
             qPrintable(run.out));
    QVERIFY2(run.out.contains("scene: 2 object(s)") && run.out.contains("(0, 0, 0) - (12, 2, 2)") &&
                 run.out.contains("trim modes unavailable (Object 'open_square.obj'"),
             qPrintable(run.out));
}

// The usage text lists the demos from the scene registry, each one loadable.
void TestCommandLine::helpListsEveryBuiltInDemo()
{
    const Run run = runTrimlab({"--help"});
    QCOMPARE(run.exitCode, 0);
    const std::vector<DemoEntry> demos = builtInDemos();
    // Both kinds of demo: meshes (demo_scenes.h) and editable surfaces (surface_scenes.h).
    QVERIFY(run.out.contains(QStringLiteral("demo:pushed-sphere ")));
    QVERIFY(run.out.contains(QStringLiteral("demo:subdivision-push ")));
    for (const DemoEntry& demo : demos) {
        const QString source = QString::fromStdString(demo.source);
        QVERIFY2(run.out.contains(source + QLatin1Char(' ')), qPrintable(source));
        QVERIFY2(run.out.contains(QString::fromUtf8(demo.description.data(), qsizetype(demo.description.size()))),
                 qPrintable(source));
        QVERIFY(!loadScene(demo.source).scene.empty());
    }
}

// The skin verb fits rigid joints unless --method says otherwise: the overview must not
// show --method as required, and it lists every method the verb accepts.
void TestCommandLine::helpShowsTheSkinMethodOptionalWithEveryChoice()
{
    const Run run = runTrimlab({"--help"});
    QCOMPARE(run.exitCode, 0);
    const QStringList lines = run.out.split(QLatin1Char('\n'));
    const auto skinLine = std::find_if(
        lines.begin(), lines.end(), [](const QString& line) { return line.contains(QStringLiteral("trimlab skin ")); });
    QVERIFY2(skinLine != lines.end(), qPrintable(run.out));
    QVERIFY2(skinLine->contains(QStringLiteral("[--method ")), qPrintable(*skinLine));
    for (const ChoiceValue& choice : skinning_parameters::kFit.choices) {
        const QString name = QString::fromUtf8(choice.name.data(), qsizetype(choice.name.size()));
        QVERIFY2(skinLine->contains(name), qPrintable(name + QStringLiteral(" missing from: ") + *skinLine));
    }
}

void TestCommandLine::openMeshRendersUntrimmedByDefault()
{
    const QString out = m_dir.filePath("open.png");
    const Run run =
        runTrimlab({"render", data("meshes/open_square.obj"), "--backend", "reference", "--size", "64x48", "-o", out});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.err.contains("note: rendering without trimming"), qPrintable(run.err));
    QVERIFY(!QImage(out).isNull());
}

// The CLI's reference backend is the in-process reference with the same fitted camera:
// its ids must be identical, its depths equal the view depth times the ray length.
void TestCommandLine::referenceBackendMatchesInProcessReference()
{
    const QString ids = m_dir.filePath("ref-ids.png");
    const QString depth = m_dir.filePath("ref.pfm");
    const Run run = runTrimlab(kPushedSphereView + QStringList{"--backend", "reference", "--ids", ids, "--depth", depth,
                                                               "-o", m_dir.filePath("ref.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));

    const LoadedScene loaded = loadScene("demo:pushed-sphere");
    const Camera camera = fitCamera(loaded.scene.worldBounds(), 256.0 / 192.0);
    TrimSettings settings;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    const ReferenceResult reference = ReferenceRenderer(loaded.scene).render(camera, 256, 192, settings);
    const TrimImage fromFile = decodeIdsPng(QImage(ids));
    const io::FloatImage distances = io::readPfm(depth.toStdString());
    int idMismatches = 0;
    int depthMismatches = 0;
    for (int y = 0; y < 192; ++y) {
        for (int x = 0; x < 256; ++x) {
            const TrimPixel& r = reference.trim.at(x, y);
            idMismatches += fromFile.at(x, y).primitiveId == r.primitiveId ? 0 : 1;
            const float d = distances.values[std::size_t(y) * 256 + x];
            const double expected =
                r.covered() ? double(r.viewDepth) * glm::length(pixelRay(camera, 256, 192, x, y).direction) : INFINITY;
            depthMismatches += (r.covered() ? std::abs(d - expected) <= 1e-5 * expected : std::isinf(d)) ? 0 : 1;
        }
    }
    QCOMPARE(idMismatches, 0);
    QCOMPARE(depthMismatches, 0);
    QVERIFY(reference.stats.coveredPixels > 3000);
}

// The acceptance check: `render` with the k+-buffer and with --backend reference
// agree on >= 99.9 % of covered pixels.
void TestCommandLine::kplusBackendAgreesWithReference()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    const QString gpuIds = m_dir.filePath("gpu-ids.png");
    const Run run = runTrimlab(kPushedSphereView + QStringList{"--ids", gpuIds, "-o", m_dir.filePath("gpu.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("0 overflowed pixels"), qPrintable(run.out));

    const LoadedScene loaded = loadScene("demo:pushed-sphere");
    const Camera camera = fitCamera(loaded.scene.worldBounds(), 256.0 / 192.0);
    TrimSettings settings;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    const ReferenceResult reference = ReferenceRenderer(loaded.scene).render(camera, 256, 192, settings);
    const test::TrimComparison comparison =
        test::compareTrimImages(decodeIdsPng(QImage(gpuIds)), idsOnly(reference.trim), reference.diagnostics);
    qInfo("%s", qPrintable(comparison.summary()));
    QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
             qPrintable(comparison.summary()));
}

// --method picks any method of the build; the statistics line names it and reports its
// geometry passes and stored and lost fragments.
void TestCommandLine::everyMethodRendersAndReportsItsStatistics()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    for (const render::MethodInfo& info : render::fragmentMethods()) {
        const QString id = QString::fromLatin1(info.id.data(), qsizetype(info.id.size()));
        const QString out = m_dir.filePath(id + ".png");
        const Run run =
            runTrimlab(kPushedSphereView + QStringList{"--method", id, "--shared-counters", "64", "-o", out});
        QVERIFY2(run.exitCode == 0, qPrintable(id + ": " + run.err));
        QVERIFY2(run.out.contains(QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()))),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("[1-9]\\d* geometry passes"))),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QRegularExpression(QStringLiteral("\\d+ stored, \\d+ lost"))), qPrintable(run.out));
        QCOMPARE(run.out.contains(QStringLiteral("S = 64")), info.usesSharedCounters);
        QVERIFY(!QImage(out).isNull());
    }
}

// `render --script --frame`: the replayed design's last frame under the dynamic rules,
// rendered by the GPU and written as ids, agrees with the in-process dynamic reference.
void TestCommandLine::scriptReplayRendersTheDynamicRulesLikeTheReference()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    const QString script = data("scripts/fig8_7_extended_tip.json");
    const QString ids = m_dir.filePath("design-ids.png");
    const Run run =
        runTrimlab({"render", "demo:sphere", "--script", script, "--frame", "2", "--clip", "0,0,-1,0", "--size",
                    "200x150", "--method", "abuffer-linked-list", "--ids", ids, "-o", m_dir.filePath("design.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("frame 2 of 2") && run.out.contains("dynamic: alternating-border on the base mesh, then "
                                                                  "confluent, confluent"),
             qPrintable(run.out));

    const LoadedScene loaded = loadScene("demo:sphere");
    const timeline::Timeline design = timeline::replayStrokeScript(loaded.scene.objects.front().mesh,
                                                                   timeline::loadStrokeScript(script.toStdString()));
    const DynamicChain chain = timeline::frameChain(design, 2, StaticRule::AlternatingBorder);
    const Camera camera = fitCamera(timeline::chainBounds(chain), 200.0 / 150.0);
    TrimSettings settings;
    settings.clip = ClipPlane{true, {0.0, 0.0, -1.0}, 0.0};
    const ReferenceResult reference = DynamicReferenceRenderer(chain).render(camera, 200, 150, settings);
    const TrimImage expected = withMeshIds(reference.trim, chain.levels.back().frame);
    const test::TrimComparison comparison =
        test::compareTrimImages(decodeIdsPng(QImage(ids)), idsOnly(expected), reference.diagnostics);
    qInfo("%s", qPrintable(comparison.summary()));
    QVERIFY(comparison.coveredPixels > 2000);
    QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
             qPrintable(comparison.summary()));
}

// A project saved before the first edit has a base mesh and no frames. Under the
// dynamic rules (the default for projects) it renders its base mesh, classified by the
// static base rule, exactly as the static classification draws it; before, it failed with
// "a dynamic chain needs one rule per set", naming no file.
void TestCommandLine::projectWithoutFramesRendersItsBaseMesh()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    QFile source(data("projects/v2_cube_cage.trimlab")); // a closed cube surface and one edit
    QVERIFY(source.open(QIODevice::ReadOnly));
    QJsonObject project = QJsonDocument::fromJson(source.readAll()).object();
    project["frames"] = QJsonArray();
    project["sets"] = QJsonArray();
    const QString path = m_dir.filePath("no-frames.trimlab");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QJsonDocument(project).toJson());
    file.close();

    const QString dynamic = m_dir.filePath("no-frames-dynamic.png");
    const Run run = runTrimlab({"render", path, "--size", "160x120", "-o", dynamic});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("frame 0 of 0") && run.out.contains("no deformation before this frame"),
             qPrintable(run.out));
    const QString plain = m_dir.filePath("no-frames-static.png");
    const Run staticRun = runTrimlab({"render", path, "--classification", "static", "--size", "160x120", "-o", plain});
    QVERIFY2(staticRun.exitCode == 0, qPrintable(staticRun.err));
    const QImage a(dynamic);
    QVERIFY(!a.isNull());
    QCOMPARE(a, QImage(plain));
    int covered = 0; // not an empty picture
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            covered += a.pixel(x, y) != a.pixel(0, 0);
    QVERIFY2(covered > 1000, qPrintable(QString::number(covered)));
}

QTEST_MAIN(TestCommandLine)
#include "tst_command_line.moc"
