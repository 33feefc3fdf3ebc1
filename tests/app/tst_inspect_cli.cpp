// `trimlab render` with the interior-inspection flags as users call it: repeated --clip,
// --cap, --csg, --object-rule and --highlight; bad combinations exit with 2 and one line;
// both backends' ids and depths agree with the in-process CPU reference.
#include "color_check.h"
#include "gl_test_context.h"
#include "ids_png.h"
#include "plain_obj.h"
#include "run_trimlab.h"
#include "trim_comparison.h"

#include "core/io/pfm_image.h"
#include "core/catalog/scene_source.h"
#include "core/trim/reference_renderer.h"
#include "core/timeline/project_file.h"
#include "core/scene/object_transform.h"
#include "core/scene/shape_generators.h"

#include <glm/geometric.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace trimlab;
using trimlab::test::decodeIdsPng;
using trimlab::test::idsOnly;
using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// The settings the CLI arguments of kTrioView mean (the cap pattern does not change ids).
TrimSettings trioSettings()
{
    TrimSettings s;
    ClipSet clips;
    clips.planes[0] = ClipPlane{true, {0.0, 0.0, -1.0}, 0.2};
    clips.planes[1] = ClipPlane{true, {0.0, -1.0, 0.0}, 0.5};
    s.setClipSet(clips);
    s.cap.enabled = true;
    s.csg.expression = parseCsgExpression("0 | 1 - 2", nullptr).value();
    s.csg.objectRules[0] = StaticRule::AlternatingBorder;
    s.rule = StaticRule::PositiveIndex;
    s.highlight.collisions = true;
    return s;
}

const QStringList kTrioView = {
    "render",     "demo:csg-trio", "--rule", "positive-index", "--clip",        "0,0,-1,0.2",           "--clip",
    "0,-1,0,0.5", "--cap",         "--csg",  "0 | 1 - 2",      "--object-rule", "0=alternating-border", "--highlight",
    "collisions", "--size",        "160x120"};

ReferenceResult trioReference(Camera* cameraOut = nullptr)
{
    const LoadedScene loaded = loadScene("demo:csg-trio");
    const Camera camera = fitCamera(loaded.scene.worldBounds(), double(kWidth) / kHeight);
    if (cameraOut)
        *cameraOut = camera;
    return ReferenceRenderer(loaded.scene).render(camera, kWidth, kHeight, trioSettings());
}

} // namespace

class TestInspectCli : public QObject {
    Q_OBJECT
private slots:
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void referenceBackendWritesCapsAndCsg();
    void gpuBackendAgreesWithReference();
    void transparencyColorsAgreeWithReference();
    void severalSourcesMakeOneScene();
    void severalSourcesBadIds_data();
    void severalSourcesBadIds();
    void sceneProjectRendersWithItsCsg();

private:
    QTemporaryDir m_dir;
};

void TestInspectCli::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QStringList base = {"render", "demo:csg-trio", "-o", "x.png"};
    QTest::newRow("cap without clip") << base + QStringList{"--cap"} << "--cap needs at least one --clip";
    QStringList seven = base;
    for (int i = 0; i < 7; ++i)
        seven << "--clip"
              << "1,0,0,0";
    QTest::newRow("seven planes") << seven << "at most 6 clipping planes";
    QTest::newRow("bad second plane") << base + QStringList{"--clip", "1,0,0,0", "--clip", "0,0,0,1"}
                                      << "--clip: plane 2";
    QTest::newRow("bad csg") << base + QStringList{"--csg", "0 | | 1"} << "--csg '0 | | 1': at character 5";
    QTest::newRow("csg id out of range") << base + QStringList{"--csg", "0 - 9"} << "object id 9 is out of range";
    QTest::newRow("csg object missing") << QStringList{"render", "demo:sphere", "--csg",     "0 & 1",
                                                       "-o",     "x.png",       "--backend", "reference"}
                                        << "--csg refers to object 1, but the scene has 1 object(s)";
    QTest::newRow("bad object rule") << base + QStringList{"--object-rule", "1:parity"}
                                     << "--object-rule must look like";
    QTest::newRow("unknown object rule") << base + QStringList{"--object-rule", "1=winding"}
                                         << "unknown rule 'winding'";
    QTest::newRow("bad highlight") << base + QStringList{"--highlight", "collisions,ghosts"}
                                   << "unknown --highlight 'ghosts'";
    QTest::newRow("csg without a rule") << base + QStringList{"--rule", "none", "--csg", "0 | 1"}
                                        << "--rule none has no interior";
    QTest::newRow("bad cap pattern") << base + QStringList{"--clip", "1,0,0,0", "--cap", "--cap-pattern", "dots"}
                                     << "unknown --cap-pattern 'dots'";
    QTest::newRow("bad transparency") << base + QStringList{"--transparency", "glass"}
                                      << "unknown --transparency 'glass'";
    QTest::newRow("alpha without transparency")
        << base + QStringList{"--ghost-alpha", "0.5"} << "--ghost-alpha needs --transparency";
    QTest::newRow("alpha out of range") << base + QStringList{"--transparency", "opaque", "--layer-alpha", "1.5"}
                                        << "--layer-alpha must be a number from 0 to 1";
    QTest::newRow("negative density") << base + QStringList{"--transparency", "translucent", "--density", "-1"}
                                      << "--density must be a number from 0";
    QTest::newRow("transparency with two-pass")
        << base + QStringList{"--transparency", "opaque", "--method", "two-pass"}
        << "--method two-pass cannot render --transparency";
    QTest::newRow("csg with a peeling method") << base + QStringList{"--csg", "0 | 1", "--method", "peeling-dual"}
                                               << "--method peeling-dual cannot render --csg";
}

void TestInspectCli::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
}

// The reference backend is the in-process reference: identical ids, and the depth image
// holds the caps' depths (on the clipping plane) where the ids are empty.
void TestInspectCli::referenceBackendWritesCapsAndCsg()
{
    const QString ids = m_dir.filePath("trio-ids.png");
    const QString depth = m_dir.filePath("trio.pfm");
    const Run run = runTrimlab(kTrioView + QStringList{"--backend", "reference", "--ids", ids, "--depth", depth, "-o",
                                                       m_dir.filePath("trio-ref.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("CSG 0 | 1 - 2") && run.out.contains("2 clipping planes") && run.out.contains("capped") &&
                 run.out.contains("cap pixels") && run.out.contains("colliding pixels"),
             qPrintable(run.out));
    Camera camera;
    const ReferenceResult reference = trioReference(&camera);
    const TrimImage fromFile = decodeIdsPng(QImage(ids));
    const io::FloatImage distances = io::readPfm(depth.toStdString());
    int idMismatches = 0, depthMismatches = 0, caps = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const TrimPixel& r = reference.trim.at(x, y);
            idMismatches += fromFile.at(x, y).primitiveId == r.primitiveId ? 0 : 1;
            const float d = distances.values[std::size_t(y) * kWidth + x];
            const double expected =
                r.covered() ? double(r.viewDepth) * glm::length(pixelRay(camera, kWidth, kHeight, x, y).direction)
                            : INFINITY;
            depthMismatches += (r.covered() ? std::abs(d - expected) <= 1e-5 * expected : std::isinf(d)) ? 0 : 1;
            caps += r.isCap() ? 1 : 0;
        }
    }
    QCOMPARE(idMismatches, 0);
    QCOMPARE(depthMismatches, 0);
    QVERIFY(caps > 300);
    QVERIFY2(run.out.contains(QStringLiteral("%1 cap pixels").arg(caps)), qPrintable(run.out));
}

void TestInspectCli::gpuBackendAgreesWithReference()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    Camera camera;
    const ReferenceResult reference = trioReference(&camera);
    for (const char* method : {"abuffer-linked-list", "kplus-array"}) {
        const QString ids = m_dir.filePath(QStringLiteral("%1-ids.png").arg(method));
        const QString depth = m_dir.filePath(QStringLiteral("%1.pfm").arg(method));
        const Run run =
            runTrimlab(kTrioView + QStringList{"--method", method, "--k", "32", "--ids", ids, "--depth", depth, "-o",
                                               m_dir.filePath(QStringLiteral("%1.png").arg(method))});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY2(run.out.contains("0 overflowed pixels") && run.out.contains("cap pixels"), qPrintable(run.out));
        // The shown surfaces, by their ids (a cap has none: it is empty in the ids image).
        const test::TrimComparison comparison =
            test::compareTrimImages(decodeIdsPng(QImage(ids)), idsOnly(reference.trim), reference.diagnostics);
        qInfo("%s: %s", method, qPrintable(comparison.summary()));
        QVERIFY(comparison.coveredPixels > 300);
        QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
                 qPrintable(comparison.summary()));
        // The caps, by the depth image: where the reference shows a cap, the file holds the
        // distance to the clipping plane (float rounding: 1e-4 relative) and no ids.
        const io::FloatImage distances = io::readPfm(depth.toStdString());
        const TrimImage fromIds = decodeIdsPng(QImage(ids));
        int caps = 0, capsAgreeing = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const TrimPixel& r = reference.trim.at(x, y);
                if (!r.isCap())
                    continue;
                ++caps;
                const double expected =
                    double(r.viewDepth) * glm::length(pixelRay(camera, kWidth, kHeight, x, y).direction);
                const float d = distances.values[std::size_t(y) * kWidth + x];
                capsAgreeing += fromIds.at(x, y).primitiveId < 0 && std::abs(d - expected) <= 1e-4 * expected ? 1 : 0;
            }
        }
        qInfo("%s: %d of %d reference cap pixels are caps in the files", method, capsAgreeing, caps);
        QVERIFY(caps > 1000);
        QVERIFY2(capsAgreeing >= caps * 999 / 1000, qPrintable(QStringLiteral("%1 of %2").arg(capsAgreeing).arg(caps)));
    }
}

// --transparency with both backends: the reference backend's PNG is the in-process
// reference's color image byte for byte; the GPU's is within 2/255 on >= 99.9 % of the
// pixels whose ray hits anything (tests/render/tst_transparency_methods.cpp says why).
void TestInspectCli::transparencyColorsAgreeWithReference()
{
    const QStringList view = {"render",         "demo:pushed-sphere",
                              "--transparency", "translucent",
                              "--layer-alpha",  "0.3",
                              "--ghost-alpha",  "0.2",
                              "--density",      "0.8",
                              "--fresnel",      "2",
                              "--size",         "160x120"};
    const Scene scene = loadScene("demo:pushed-sphere").scene;
    TrimSettings settings;
    settings.transparency = {true, TrimDisplay::Translucent, 0.3, 0.2, 0.8, 2.0};
    const Camera camera = fitCamera(scene.worldBounds(), double(kWidth) / kHeight);
    const ReferenceResult reference = ReferenceRenderer(scene).render(camera, kWidth, kHeight, settings);
    const QString cpu = m_dir.filePath("xray-ref.png");
    const Run run = runTrimlab(view + QStringList{"--backend", "reference", "-o", cpu});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("X-ray translucent"), qPrintable(run.out));
    QCOMPARE(QImage(cpu).convertToFormat(QImage::Format_RGBA8888), test::rgbaToImage(reference.color));
    TRIMLAB_SKIP_WITHOUT_GL();
    const QString gpu = m_dir.filePath("xray-gpu.png");
    const Run gpuRun = runTrimlab(view + QStringList{"--method", "s-buffer", "-o", gpu});
    QVERIFY2(gpuRun.exitCode == 0, qPrintable(gpuRun.err));
    const QImage image(gpu);
    const test::ColorComparison colors =
        test::compareColors(image, TrimImage(kWidth, kHeight), reference.color, reference.diagnostics, 2);
    qInfo("%s", qPrintable(colors.summary()));
    const auto violation = test::colorViolation(colors, image, reference.color, "cli-xray", 0.999, 1000);
    QVERIFY2(!violation, violation ? qPrintable(*violation) : "");
}

// `trimlab render A B --object-transform 1=... --csg "0 - 1" --rule nonzero`: the two
// sources are objects 0 and 1 of one scene; object 1 is moved and shrunk; the GPU's ids
// agree with the in-process reference of the same composed scene, and nonzero keeps the
// pushed sphere's finger below the sphere (w = -1), which the difference leaves alone.
void TestInspectCli::severalSourcesMakeOneScene()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    const QString ball = m_dir.filePath("ball.obj");
    QVERIFY(test::writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 3), ball));
    const QString ids = m_dir.filePath("two-ids.png");
    const Run run = runTrimlab({"render", "demo:pushed-sphere", ball, "--object-transform", "1=0.6,0.2,0,0,45,0,0.7",
                                "--csg", "0 - 1", "--rule", "nonzero", "--method", "abuffer-linked-list", "--size",
                                "160x120", "--ids", ids, "-o", m_dir.filePath("two.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("pushed-sphere + ball.obj") && run.out.contains("nonzero, CSG 0 - 1"),
             qPrintable(run.out));

    LoadedScene loaded = loadScenes({"demo:pushed-sphere", ball.toStdString()});
    QCOMPARE(loaded.scene.objects.size(), std::size_t(2));
    ObjectTransform placed;
    placed.translation = {0.6, 0.2, 0.0};
    placed.rotationDegrees = {0.0, 45.0, 0.0};
    placed.scale = 0.7;
    loaded.scene.objects[1].modelMatrix = placed.modelMatrix();
    TrimSettings settings;
    settings.rule = StaticRule::Nonzero;
    settings.csg.expression = parseCsgExpression("0 - 1", nullptr).value();
    const Camera camera = fitCamera(loaded.scene.worldBounds(), double(kWidth) / kHeight);
    const ReferenceResult reference = ReferenceRenderer(loaded.scene).render(camera, kWidth, kHeight, settings);
    const test::TrimComparison comparison =
        test::compareTrimImages(decodeIdsPng(QImage(ids)), idsOnly(reference.trim), reference.diagnostics);
    qInfo("%s", qPrintable(comparison.summary()));
    QVERIFY(comparison.coveredPixels > 2000);
    QVERIFY2(comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05,
             qPrintable(comparison.summary()));
    // The ball (object 1) bites into the sphere: some shown pixels are its inner faces.
    int ballPixels = 0;
    for (const TrimPixel& p : reference.trim.pixels)
        ballPixels += p.covered() && p.objectId == 1 ? 1 : 0;
    QVERIFY2(ballPixels > 100, qPrintable(QString::number(ballPixels)));
}

void TestInspectCli::severalSourcesBadIds_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QStringList two = {"render", "demo:sphere", "demo:pushed-sphere", "--backend", "reference", "-o", "x.png"};
    QTest::newRow("transform of a missing object") << two + QStringList{"--object-transform", "2=1,0,0"}
                                                   << "--object-transform names object 2, but the scene has 2";
    QTest::newRow("rule of a missing object")
        << two + QStringList{"--object-rule", "3=parity"} << "--object-rule refers to object 3";
    QTest::newRow("csg of a missing object") << two + QStringList{"--csg", "0 - 2"} << "--csg refers to object 2";
    QTest::newRow("transform needs 3, 6 or 7 numbers")
        << two + QStringList{"--object-transform", "1=1,2"} << "3, 6 or 7 numbers";
    QTest::newRow("transform with a zero scale")
        << two + QStringList{"--object-transform", "1=0,0,0,0,0,0,0"} << "the scale must be positive";
    QTest::newRow("project among several sources")
        << QStringList{"render", "demo:sphere", "a.trimlab", "-o", "x.png"} << "take exactly one source";
}

void TestInspectCli::severalSourcesBadIds()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
}

// A scene project renders with the CSG, object rules and static rule it saved (the
// reference backend is the in-process reference: identical ids), and info names its CSG.
void TestInspectCli::sceneProjectRendersWithItsCsg()
{
    timeline::ProjectScene saved;
    saved.objects.push_back({"body", makeIcosphere(glm::dvec3(0.0), 1.0, 3), glm::dmat4(1.0)});
    ObjectTransform placed;
    placed.translation = {0.7, 0.1, 0.2};
    placed.scale = 0.6;
    saved.objects.push_back({"bite", makeIcosphere(glm::dvec3(0.0), 1.0, 2), placed.modelMatrix()});
    saved.csg.expression = parseCsgExpression("0 - 1", nullptr).value();
    saved.csg.objectRules[1] = StaticRule::Nonzero;
    timeline::ProjectExtras extras;
    extras.staticRule = StaticRule::Parity;
    const QString project = m_dir.filePath("assembly.trimlab");
    timeline::saveSceneProject(saved, project.toStdString(), extras);

    const QString ids = m_dir.filePath("assembly-ids.png");
    const Run run = runTrimlab({"render", project, "--backend", "reference", "--size", "160x120", "--ids", ids, "-o",
                                m_dir.filePath("assembly.png")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("assembly.trimlab: 160x120, parity, CSG 0 - 1"), qPrintable(run.out));
    const LoadedScene loaded = loadScene(project.toStdString());
    TrimSettings settings;
    settings.rule = StaticRule::Parity;
    settings.csg = saved.csg;
    const Camera camera = fitCamera(loaded.scene.worldBounds(), double(kWidth) / kHeight);
    const ReferenceResult reference = ReferenceRenderer(loaded.scene).render(camera, kWidth, kHeight, settings);
    const TrimImage fromFile = decodeIdsPng(QImage(ids));
    int mismatches = 0, bitePixels = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            mismatches += fromFile.at(x, y).primitiveId == reference.trim.at(x, y).primitiveId ? 0 : 1;
            bitePixels += reference.trim.at(x, y).objectId == 1 ? 1 : 0;
        }
    QCOMPARE(mismatches, 0);
    QVERIFY(bitePixels > 100); // the difference shows the bite's inner faces

    const Run info = runTrimlab({"info", project});
    QCOMPARE(info.exitCode, 0);
    QVERIFY2(info.out.contains("object 1: bite") && info.out.contains("saved CSG: 0 - 1"), qPrintable(info.out));
}

QTEST_MAIN(TestInspectCli)
#include "tst_inspect_cli.moc"
