// `trimlab skin` as scripts call it: bad arguments exit 2 and bad input exits 1, each with
// one "trimlab: error: ..." line; a run prints sizes, bones, method, the E_RMS of the fit
// and of the exported file and per-stage times, and writes a glTF that the Khronos glTF
// Validator accepts and that, loaded back, has exactly the printed exported E_RMS.
#include "gltf_validation.h"
#include "run_trimlab.h"
#include "test_paths.h"

#include "core/animation/animation_loader.h"
#include "core/skinning/skinning_error.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

QString animation(const QString& relative)
{
    return QString::fromStdString(test::testDataPath(("animations/" + relative).toStdString()).string());
}

// The number after `label` in the verb's output ("E_RMS exported: 0.1234").
double printedNumber(const QString& out, const QString& label)
{
    const QRegularExpression number(QRegularExpression::escape(label) + QStringLiteral(R"(\s*([-+0-9.eE]+))"));
    const QRegularExpressionMatch match = number.match(out);
    return match.hasMatch() ? match.captured(1).toDouble() : std::nan("");
}

// The printed exported E_RMS is that of the written file against the input animation.
void requireExportedErrorMatchesFile(const QString& source, const QString& file, const QString& out)
{
    const MeshAnimation original = loadAnimation(source.toStdString());
    const MeshAnimation written = loadAnimation(file.toStdString());
    QCOMPARE(written.poseCount(), original.poseCount());
    QCOMPARE(written.triangles, original.triangles);
    const SkinningError error = measureSkinningError(animationPositions(original), animationPositions(written));
    const double printed = printedNumber(out, "E_RMS exported:");
    QVERIFY2(std::abs(printed - error.eRms) <= 1e-3 * error.eRms + 1e-3,
             qPrintable(QString("printed %1, file %2").arg(printed).arg(error.eRms)));
}

} // namespace

class TestSkinVerb : public QObject {
    Q_OBJECT
private slots:
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void badInputsExitWithOne_data();
    void badInputsExitWithOne();
    void writesValidRigidGlb();
    void writesMorphTargets();
    void skinsGltfAnimation();
    void helpExitsWithZero();

private:
    QTemporaryDir m_dir;
};

void TestSkinVerb::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QString bar = animation("bar");
    const QStringList tail = {"-o", "x.glb"};
    QTest::newRow("no animation") << (QStringList{"skin", "--bones", "2", "--method", "lbs"} + tail)
                                  << "exactly one animation";
    QTest::newRow("no bones") << (QStringList{"skin", bar, "--method", "lbs"} + tail) << "--bones B and --method";
    QTest::newRow("no method") << (QStringList{"skin", bar, "--bones", "2"} + tail) << "--bones B and --method";
    QTest::newRow("zero bones") << (QStringList{"skin", bar, "--bones", "0", "--method", "lbs"} + tail)
                                << "--bones must be an integer from 1 to 65535";
    QTest::newRow("text bones") << (QStringList{"skin", bar, "--bones", "many", "--method", "lbs"} + tail)
                                << "--bones must be an integer";
    // Output paths are checked before any work (app/output_paths.h): exit 2, not 1.
    QTest::newRow("unwritable output") << QStringList{"skin", bar, "--bones", "2", "--method", "dqs", "-o",
                                                      "/nonexistent/x.glb"}
                                       << "-o /nonexistent/x.glb: the folder /nonexistent does not exist";
    QTest::newRow("bad method") << (QStringList{"skin", bar, "--bones", "2", "--method", "sad"} + tail)
                                << "unknown --method 'sad' (use lbs or dqs)";
    QTest::newRow("bad chain") << (QStringList{"skin", bar, "--bones", "2", "--method", "lbs", "--chain", "x"} + tail)
                               << "unknown --chain 'x'";
    QTest::newRow("bad corrections") << (QStringList{"skin", bar, "--bones", "2", "--method", "lbs", "--corrections",
                                                     "v,x"} + tail)
                                     << "unknown --corrections 'v,x'";
    QTest::newRow("bad fps") << (QStringList{"skin", bar, "--bones", "2", "--method", "lbs", "--fps", "0"} + tail)
                             << "--fps must be a number";
    QTest::newRow("bad export") << (QStringList{"skin", bar, "--bones", "2", "--method", "lbs", "--export", "fbx"} + tail)
                                << "unknown --export 'fbx'";
    QTest::newRow("bad interpolation") << (QStringList{"skin", bar, "--bones", "2", "--method", "lbs",
                                                       "--interpolation", "cubic"} + tail)
                                       << "unknown --interpolation";
    QTest::newRow("no output") << QStringList{"skin", bar, "--bones", "2", "--method", "lbs"} << "-o out.glb";
    QTest::newRow("bad output") << QStringList{"skin", bar, "--bones", "2", "--method", "lbs", "-o", "x.obj"}
                                << ".glb or .gltf";
    QTest::newRow("unknown option") << (QStringList{"skin", bar, "--bones", "2", "--method", "lbs", "--frobnicate"} + tail)
                                    << "frobnicate";
}

void TestSkinVerb::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
}

void TestSkinVerb::badInputsExitWithOne_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QStringList tail = {"--bones", "2", "--method", "dqs", "-o", m_dir.filePath("bad.glb")};
    QTest::newRow("missing folder") << (QStringList{"skin", "/nonexistent/poses"} + tail) << "/nonexistent/poses";
    QTest::newRow("poses disagree (faces)") << (QStringList{"skin", animation("mismatched_faces")} + tail)
                                            << "mesh_0002.obj: face 5 is (2, 8, 9) but the first pose has (2, 8, 7)";
    QTest::newRow("poses disagree (vertices)") << (QStringList{"skin", animation("mismatched_vertices")} + tail)
                                               << "mesh_0001.obj: has 11 vertices";
    QTest::newRow("broken pose") << (QStringList{"skin", animation("broken_pose")} + tail) << "mesh_0001.obj:9:";
    QTest::newRow("more bones than vertices")
        << QStringList{"skin", animation("bar"), "--bones", "11", "--method", "lbs", "-o", m_dir.filePath("b.glb")}
        << "cannot make 11 segments of 10 vertices";
    QTest::newRow("one pose") << (QStringList{"skin", animation("bar/bar_1.*")} + tail) << "needs at least 2";
}

void TestSkinVerb::badInputsExitWithOne()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 1, message);
}

void TestSkinVerb::writesValidRigidGlb()
{
    const QString out = m_dir.filePath("box.glb");
    const QString source = animation("folding_box");
    const Run run = runTrimlab({"skin", source, "--bones", "2", "--method", "dqs", "--corrections", "v,w", "--threads",
                                "2", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    for (const char* line : {"3 poses, ", " vertices, ", "bones: 2 ", "method: DQS, pose-to-pose; corrections: v (",
                             ", w (", "E_RMS fit: ", "E_RMS/diagonal ", "E_RMS exported: ", "rigid transforms, 2 joints",
                             "times (ms): load ", "segmentation ", "weights ", "fit ", "corrections ", "export ",
                             "wrote "})
        QVERIFY2(run.out.contains(QString::fromLatin1(line)), qPrintable(QString(line) + " missing in\n" + run.out));
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.read(4), QByteArray("glTF"));
    test::requireValidGltf(out.toStdString());
    requireExportedErrorMatchesFile(source, out, run.out);
}

void TestSkinVerb::writesMorphTargets()
{
    const QString out = m_dir.filePath("box.gltf");
    const QString source = animation("folding_box");
    const Run run = runTrimlab({"skin", source, "--bones", "3", "--method", "lbs", "--chain", "rest-to-pose", "--export",
                                "morph", "--fps", "12", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("method: LBS, rest-to-pose; corrections: none") && run.out.contains("morph targets"),
             qPrintable(run.out));
    // Morph targets are exact: the file's error is the fit's.
    QVERIFY(std::abs(printedNumber(run.out, "E_RMS fit:") - printedNumber(run.out, "E_RMS exported:")) < 2e-3);
    test::requireValidGltf(out.toStdString());
    requireExportedErrorMatchesFile(source, out, run.out);
}

void TestSkinVerb::skinsGltfAnimation()
{
    const QString out = m_dir.filePath("bar.glb");
    const QString source = animation("skinned_bar.gltf");
    const Run run = runTrimlab({"skin", source, "--bones", "2", "--method", "lbs", "--interpolation", "step", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("bones: 2 ") && run.out.contains("rigid approximation of an affine fit"),
             qPrintable(run.out));
    QVERIFY(printedNumber(run.out, "E_RMS exported:") >= printedNumber(run.out, "E_RMS fit:") - 1e-3);
    test::requireValidGltf(out.toStdString());
    requireExportedErrorMatchesFile(source, out, run.out);
}

void TestSkinVerb::helpExitsWithZero()
{
    const Run run = runTrimlab({"skin", "--help"});
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("Usage: trimlab skin") && run.out.contains("--bones") && run.out.contains("--corrections"),
             qPrintable(run.out));
}

QTEST_GUILESS_MAIN(TestSkinVerb)
#include "tst_skin_verb.moc"
