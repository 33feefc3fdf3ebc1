// `trimlab trim` as scripts call it: the trimmed solid of a demo and of a scene composed
// from several sources (placed, CSG) written in every format, read back by TrimLab's own
// loaders as a closed, consistently oriented surface with the volume the verb printed;
// the glTF passes the Khronos validator; bad arguments exit 2, open surfaces 1, unless
// --close-holes closes them (for `trimlab info` too); --clip cuts the solid and caps it;
// --poses exports an animation pose by pose, as files or as one glTF that plays them.
#include "gltf_validation.h"
#include "gltf_values.h"
#include "plain_obj.h"
#include "run_trimlab.h"
#include "test_paths.h"

#include "core/catalog/scene_source.h"
#include "core/io/file_bytes.h"
#include "core/mesh/gltf_document.h"
#include "core/mesh/mesh_validation.h"
#include "core/mesh/hole_fans.h"
#include "core/scene/shape_generators.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

// The volume on the verb's first output line ("...; volume V").
double printedVolume(const QString& out)
{
    const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("volume ([-0-9.e+]+)")).match(out);
    return m.hasMatch() ? m.captured(1).toDouble() : std::nan("");
}

} // namespace

class TestTrimVerb : public QObject {
    Q_OBJECT
private slots:
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void openSurfaceExitsWithOne();
    void pushedSphereInEveryFormat_data();
    void pushedSphereInEveryFormat();
    void severalSourcesWithCsg();
    void closeHolesTrimsAnOpenMesh();
    void clipCutsAndCaps();
    void posesExportEachPoseTrimmed();
    void posesAsOneGltfSequence();
    void posesRefuseBadArguments_data();
    void posesRefuseBadArguments();

private:
    QTemporaryDir m_dir;
};

void TestTrimVerb::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("no output") << QStringList{"trim", "demo:sphere"} << "-o out.obj";
    QTest::newRow("no source") << QStringList{"trim", "-o", "x.obj"} << "at least one source";
    QTest::newRow("unknown format") << QStringList{"trim", "demo:sphere", "-o", "x.xyz"} << "unknown mesh format";
    QTest::newRow("rule none") << QStringList{"trim", "demo:sphere", "--rule", "none", "-o", "x.obj"}
                               << "--rule none keeps no solid";
    QTest::newRow("unknown rule") << QStringList{"trim", "demo:sphere", "--rule", "odd", "-o", "x.obj"}
                                  << "unknown --rule 'odd'";
    QTest::newRow("csg of a missing object")
        << QStringList{"trim", "demo:sphere", "--csg", "0 - 1", "-o", "x.obj"} << "--csg refers to object 1";
}

void TestTrimVerb::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
}

void TestTrimVerb::openSurfaceExitsWithOne()
{
    TriangleMesh square;
    square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    const QString path = m_dir.filePath("square.obj");
    QVERIFY(test::writePlainObj(square, path));
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab({"trim", path, "-o", m_dir.filePath("square-out.obj")}), 1,
                                  "has no inside to export");
    QVERIFY(!QFile::exists(m_dir.filePath("square-out.obj")));
}

void TestTrimVerb::pushedSphereInEveryFormat_data()
{
    QTest::addColumn<QString>("extension");
    for (const char* extension : {"obj", "ply", "stl", "glb", "gltf"})
        QTest::newRow(extension) << QString(extension);
}

// The pushed sphere under the alternating border rule is the sphere with a tunnel: a
// closed surface of genus 1, whatever format carries it.
void TestTrimVerb::pushedSphereInEveryFormat()
{
    QFETCH(QString, extension);
    const QString out = m_dir.filePath("pushed." + extension);
    const Run run = runTrimlab({"trim", "demo:pushed-sphere", "--rule", "alternating-border", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("pushed-sphere: alternating-border -> ") && run.out.contains("closed"),
             qPrintable(run.out));
    const LoadedScene loaded = loadScene(out.toStdString());
    QCOMPARE(loaded.reports.size(), std::size_t(1));
    const MeshValidationReport& report = loaded.reports.front();
    QVERIFY2(report.closed() && report.trimmable(), formatReport(report, "export").c_str());
    QCOMPARE(report.genus, std::optional<std::int64_t>(1));
    QVERIFY2(std::abs(report.signedVolume - printedVolume(run.out)) <= 1e-4 * std::abs(report.signedVolume),
             qPrintable(QString("%1 vs %2").arg(report.signedVolume).arg(printedVolume(run.out))));
    if (extension == QLatin1String("glb") || extension == QLatin1String("gltf"))
        test::requireValidGltf(out.toStdString());
}

// A ball file moved into the sphere demo and subtracted: a sphere with a bite, closed.
void TestTrimVerb::severalSourcesWithCsg()
{
    const QString ball = m_dir.filePath("ball.obj");
    QVERIFY(test::writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 2), ball));
    const QString out = m_dir.filePath("bitten.obj");
    const Run run = runTrimlab({"trim", "demo:sphere", ball, "--object-transform", "1=0.8,0.1,0,0,0,0,0.5", "--csg",
                                "0 - 1", "--rule", "nonzero", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("sphere + ball.obj: nonzero, CSG 0 - 1 -> "), qPrintable(run.out));
    const LoadedScene loaded = loadScene(out.toStdString());
    const MeshValidationReport& report = loaded.reports.front();
    QVERIFY2(report.closed() && report.trimmable(), formatReport(report, "export").c_str());
    QCOMPARE(report.genus, std::optional<std::int64_t>(0));
    // Less than the whole sphere, more than the sphere without the ball's full volume.
    const double sphere = loadScene("demo:sphere").reports.front().signedVolume;
    const double ball05 = 4.0 / 3.0 * M_PI * 0.125;
    QVERIFY2(report.signedVolume < sphere && report.signedVolume > sphere - ball05,
             qPrintable(QString("%1 (sphere %2, ball %3)").arg(report.signedVolume).arg(sphere).arg(ball05)));
}

// A sphere with one triangle missing: refused as open, with the remedy named; with
// --close-holes the hole gets a fan of 3 triangles and the solid is that closed sphere,
// its volume the closed mesh's. `trimlab info --close-holes` reports the closed mesh.
void TestTrimVerb::closeHolesTrimsAnOpenMesh()
{
    TriangleMesh holed = makeIcosphere(glm::dvec3(0.0), 1.0, 2);
    holed.triangles.erase(holed.triangles.begin());
    const QString path = m_dir.filePath("holed.obj");
    QVERIFY(test::writePlainObj(holed, path));
    const QString out = m_dir.filePath("holed-trimmed.obj");

    const Run open = runTrimlab({"trim", path, "-o", out});
    QCOMPARE(open.exitCode, 1);
    QVERIFY2(open.err.contains("3 boundary edges") && open.err.contains("--close-holes"), qPrintable(open.err));
    QVERIFY(!QFile::exists(out));

    const Run closed = runTrimlab({"trim", path, "--close-holes", "-o", out});
    QVERIFY2(closed.exitCode == 0, qPrintable(closed.err));
    QVERIFY2(closed.err.contains("closed 1 hole of 3 edges in holed.obj"), qPrintable(closed.err));
    const LoadedScene written = loadScene(out.toStdString());
    const MeshValidationReport& report = written.reports.front();
    QVERIFY2(report.trimmable(), report.trimUnavailableReason().c_str());
    const double expected = validateMesh(closeHoles(holed)).signedVolume;
    QVERIFY2(std::abs(report.signedVolume - expected) < 1e-6 * expected,
             qPrintable(QStringLiteral("%1 vs %2").arg(report.signedVolume, 0, 'g', 17).arg(expected, 0, 'g', 17)));
    QVERIFY2(std::abs(printedVolume(closed.out) - expected) < 1e-5 * expected, qPrintable(closed.out));

    const QRegularExpression closedYes(QStringLiteral("closed:\\s+yes"));
    const Run infoOpen = runTrimlab({"info", path});
    QVERIFY2(infoOpen.exitCode == 0 && !infoOpen.out.contains(closedYes), qPrintable(infoOpen.out));
    const Run infoClosed = runTrimlab({"info", path, "--close-holes"});
    QVERIFY2(infoClosed.exitCode == 0 && infoClosed.out.contains(closedYes), qPrintable(infoClosed.out));
    QVERIFY2(infoClosed.err.contains("closed 1 hole of 3 edges"), qPrintable(infoClosed.err));
}

// The pushed sphere cut by a plane and capped, then by the flipped plane: two closed
// pieces whose volumes add up to the whole solid's; a bad plane exits with 2.
void TestTrimVerb::clipCutsAndCaps()
{
    const QString whole = m_dir.filePath("whole.obj");
    const QString front = m_dir.filePath("front.obj");
    const QString back = m_dir.filePath("back.obj");
    const Run all = runTrimlab({"trim", "demo:pushed-sphere", "-o", whole});
    QVERIFY2(all.exitCode == 0, qPrintable(all.err));
    const Run cutFront = runTrimlab({"trim", "demo:pushed-sphere", "--clip", "0.3,0,-1,0.1", "-o", front});
    QVERIFY2(cutFront.exitCode == 0, qPrintable(cutFront.err));
    QVERIFY2(cutFront.out.contains("cut by 1 clipping plane") && cutFront.out.contains("closed"),
             qPrintable(cutFront.out));
    const Run cutBack = runTrimlab({"trim", "demo:pushed-sphere", "--clip", "-0.3,0,1,-0.1", "-o", back});
    QVERIFY2(cutBack.exitCode == 0, qPrintable(cutBack.err));
    const double sum = printedVolume(cutFront.out) + printedVolume(cutBack.out);
    QVERIFY(printedVolume(cutFront.out) > 0.0 && printedVolume(cutBack.out) > 0.0);
    QVERIFY2(std::abs(sum - printedVolume(all.out)) <= 1e-5 * printedVolume(all.out),
             qPrintable(QStringLiteral("%1 + %2 vs %3")
                            .arg(printedVolume(cutFront.out))
                            .arg(printedVolume(cutBack.out))
                            .arg(printedVolume(all.out))));
    for (const QString& path : {front, back}) {
        const MeshValidationReport& report = loadScene(path.toStdString()).reports.front();
        QVERIFY2(report.trimmable(), report.trimUnavailableReason().c_str());
    }
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab({"trim", "demo:sphere", "--clip", "0,0,0,1", "-o", front}), 2, "--clip");
}

namespace {

const QString kFoldingBox = QString::fromStdString(test::testDataPath("animations/folding_box").string());

// The "... -> PATH: ...; volume V" line of pose `pose` in the verb's output.
double poseVolume(const QString& out, int pose)
{
    const QRegularExpression line(QStringLiteral("pose %1 -> [^\n]*volume ([-0-9.e+]+)").arg(pose));
    const QRegularExpressionMatch m = line.match(out);
    return m.hasMatch() ? m.captured(1).toDouble() : std::nan("");
}

} // namespace

// The folding box animation: poses 0 and 1 are simple, pose 2 folds through itself. Each
// pose's file is the trim of that pose alone (the same volume as `trim` of the pose's own
// mesh file), closed, and pose 2's is smaller than its self-crossing input.
void TestTrimVerb::posesExportEachPoseTrimmed()
{
    const QString pattern = m_dir.filePath("box_%04d.obj");
    const Run run = runTrimlab({"trim", kFoldingBox, "--poses", "0:2", "-o", pattern});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("3 poses trimmed by alternating-border"), qPrintable(run.out));
    for (int pose = 0; pose <= 2; ++pose) {
        const QString path = m_dir.filePath(QStringLiteral("box_%1.obj").arg(pose, 4, 10, QLatin1Char('0')));
        QVERIFY2(QFile::exists(path), qPrintable(path));
        const MeshValidationReport& written = loadScene(path.toStdString()).reports.front();
        QVERIFY2(written.trimmable(), written.trimUnavailableReason().c_str());
        const QString own = m_dir.filePath(QStringLiteral("own_%1.obj").arg(pose));
        const QString input = QStringLiteral("%1/pose_%2.obj").arg(kFoldingBox).arg(pose);
        const Run single = runTrimlab({"trim", input, "-o", own});
        QVERIFY2(single.exitCode == 0, qPrintable(single.err));
        const double expected = printedVolume(single.out);
        QVERIFY2(std::abs(poseVolume(run.out, pose) - expected) <= 1e-9 * expected, qPrintable(run.out));
        QVERIFY2(std::abs(written.signedVolume - expected) <= 1e-5 * expected,
                 qPrintable(QStringLiteral("pose %1: %2 vs %3").arg(pose).arg(written.signedVolume).arg(expected)));
        if (pose == 2) {
            const double crossing = loadScene(input.toStdString()).reports.front().signedVolume;
            QVERIFY2(expected < crossing - 0.1, qPrintable(QStringLiteral("%1 vs %2").arg(expected).arg(crossing)));
        }
    }
    // --pose N writes the one pose, to a plain name or to the pattern's name for N.
    const Run one = runTrimlab({"trim", kFoldingBox, "--pose", "2", "-o", m_dir.filePath("one_%d.stl")});
    QVERIFY2(one.exitCode == 0, qPrintable(one.err));
    QVERIFY(QFile::exists(m_dir.filePath("one_2.stl")));
    QVERIFY2(std::abs(poseVolume(one.out, 2) - poseVolume(run.out, 2)) <= 1e-12, qPrintable(one.out));
}

// One .glb for the sequence: it validates, holds one node per pose under "sequence" with
// that pose's trimmed triangles, and an animation that shows node k alone from k/fps on
// (STEP scale keys).
void TestTrimVerb::posesAsOneGltfSequence()
{
    const QString out = m_dir.filePath("box-sequence.glb");
    const Run run = runTrimlab({"trim", kFoldingBox, "--poses", "0:2", "--fps", "10", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("3 poses, one node each, shown in turn at 10 fps"), qPrintable(run.out));
    test::requireValidGltf(out.toStdString());
    QVERIFY(!QTest::currentTestFailed());
    const tinygltf::Model model =
        parseGltfDocument(io::readFileBytes(out.toStdString(), std::size_t(1) << 30), "box-sequence.glb", {});
    QCOMPARE(model.scenes.size(), std::size_t(1));
    const tinygltf::Node& root = model.nodes[std::size_t(model.scenes[0].nodes.at(0))];
    QCOMPARE(root.name, std::string("sequence"));
    QCOMPARE(root.children.size(), std::size_t(3));
    QCOMPARE(model.animations.size(), std::size_t(1));
    const tinygltf::Animation& animation = model.animations[0];
    QCOMPARE(animation.channels.size(), std::size_t(3));
    for (int k = 0; k < 3; ++k) {
        const int node = root.children[std::size_t(k)];
        const tinygltf::Node& child = model.nodes[std::size_t(node)];
        QCOMPARE(child.name, QStringLiteral("pose_%1").arg(k, 4, 10, QLatin1Char('0')).toStdString());
        const QString single = m_dir.filePath(QStringLiteral("seq_%1.obj").arg(k));
        QVERIFY(runTrimlab({"trim", kFoldingBox, "--pose", QString::number(k), "-o", single}).exitCode == 0);
        const std::size_t triangles = loadScene(single.toStdString()).scene.objects.front().mesh.triangles.size();
        const tinygltf::Primitive& primitive = model.meshes[std::size_t(child.mesh)].primitives.at(0);
        QCOMPARE(model.accessors[std::size_t(primitive.indices)].count, 3 * triangles);
        QCOMPARE(child.scale.empty(), k == 0); // only the first pose shows without the animation
        const auto channel = std::find_if(animation.channels.begin(), animation.channels.end(),
                                          [&](const tinygltf::AnimationChannel& c) { return c.target_node == node; });
        QVERIFY(channel != animation.channels.end());
        QCOMPARE(channel->target_path, std::string("scale"));
        const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(channel->sampler)];
        QCOMPARE(sampler.interpolation, std::string("STEP"));
        // STEP: the scale at time t is the value of the last key at or before t. At pose j's
        // time j/fps node k has scale 1 exactly when j = k.
        const std::vector<float> times = test::gltfFloats(model, sampler.input);
        const std::vector<float> scales = test::gltfFloats(model, sampler.output);
        QCOMPARE(scales.size(), 3 * times.size());
        for (int j = 0; j < 3; ++j) {
            const float t = float(j) / 10.0f;
            std::size_t key = 0;
            while (key + 1 < times.size() && times[key + 1] <= t)
                ++key;
            QVERIFY(times[0] <= t);
            QCOMPARE(scales[3 * key], j == k ? 1.0f : 0.0f);
        }
    }
}

void TestTrimVerb::posesRefuseBadArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QString bar = QString::fromStdString(test::testDataPath("animations/bar").string());
    QTest::newRow("no pose number") << QStringList{"trim", kFoldingBox, "--poses", "0:2", "-o", "x.obj"} << 2
                                    << "needs the pose number";
    QTest::newRow("fps without poses") << QStringList{"trim", "demo:sphere", "--fps", "30", "-o", "x.obj"} << 2
                                       << "--fps is the rate";
    QTest::newRow("csg of an animation") << QStringList{"trim",  kFoldingBox, "--poses", "0:1",
                                                        "--csg", "0",         "-o",      "x_%d.obj"}
                                         << 2 << "one object";
    QTest::newRow("pose past the end") << QStringList{"trim", kFoldingBox, "--poses", "0:9", "-o", "x_%d.obj"} << 2
                                       << "pose 9 does not exist";
    QTest::newRow("open animation") << QStringList{"trim", bar, "--poses", "0:2", "-o", "x_%d.obj"} << 1
                                    << "--close-holes";
}

void TestTrimVerb::posesRefuseBadArguments()
{
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    for (QString& argument : arguments)
        if (argument.startsWith(QLatin1String("x")))
            argument = m_dir.filePath(argument);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), exitCode, message);
    QVERIFY(QDir(m_dir.path()).entryList({QStringLiteral("x*")}).isEmpty()); // nothing written
}

QTEST_GUILESS_MAIN(TestTrimVerb)
#include "tst_trim_verb.moc"
