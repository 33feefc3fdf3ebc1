// `trimlab segment` as scripts call it: bad arguments exit 2 and bad input exits 1, each
// with one "trimlab: error: ..." line; a run prints the segment count and the per-stage
// times and writes JSON (the documented fields), CSV or glTF.
#include "run_trimlab.h"
#include "test_paths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

QString animation(const QString& relative)
{
    return QString::fromStdString(trimlab::test::testDataPath(("animations/" + relative).toStdString()).string());
}

} // namespace

class TestSegmentVerb : public QObject {
    Q_OBJECT
private slots:
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void badInputsExitWithOne_data();
    void badInputsExitWithOne();
    void writesDocumentedJson();
    void writesCsvAndGltf();
    void segmentsGltfAnimation();

private:
    QTemporaryDir m_dir;
};

void TestSegmentVerb::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QString bar = animation("bar");
    QTest::newRow("no animation") << QStringList{"segment", "--clusters", "4", "--h", "0.1", "-o", "x.json"}
                                  << "exactly one animation";
    QTest::newRow("no clusters") << QStringList{"segment", bar, "--h", "0.1", "-o", "x.json"}
                                 << "--clusters N and --h H";
    QTest::newRow("no h") << QStringList{"segment", bar, "--clusters", "4", "-o", "x.json"} << "--clusters N and --h H";
    QTest::newRow("h too large") << QStringList{"segment", bar, "--clusters", "4", "--h", "1.5", "-o", "x.json"}
                                 << "--h must be a number from 0 to 1";
    QTest::newRow("zero clusters") << QStringList{"segment", bar, "--clusters", "0", "--h", "0.1", "-o", "x.json"}
                                   << "--clusters must be an integer";
    QTest::newRow("bad feature") << QStringList{"segment", bar,         "--clusters", "4",  "--h",
                                                "0.1",     "--feature", "speed",      "-o", "x.json"}
                                 << "unknown --feature 'speed'";
    // Output paths are checked before any work (app/output_paths.h): exit 2, not 1.
    QTest::newRow("unwritable output") << QStringList{"segment", bar,   "--clusters", "3",
                                                      "--h",     "0.1", "-o",         "/nonexistent/x.json"}
                                       << "-o /nonexistent/x.json: the folder /nonexistent does not exist";
    QTest::newRow("bad method") << QStringList{"segment", bar,        "--clusters", "4",  "--h",
                                               "0.1",     "--method", "kmeans",     "-o", "x.json"}
                                << "unknown --method 'kmeans'";
    QTest::newRow("bad reference") << QStringList{"segment", bar,           "--clusters", "4",  "--h",
                                                  "0.1",     "--reference", "first",      "-o", "x.json"}
                                   << "unknown --reference";
    QTest::newRow("bad mode") << QStringList{"segment", bar,      "--clusters", "4",  "--h",
                                             "0.1",     "--mode", "both",       "-o", "x.json"}
                              << "unknown --mode";
    QTest::newRow("bad fps") << QStringList{"segment", bar,     "--clusters", "4",  "--h",
                                            "0.1",     "--fps", "-3",         "-o", "x.json"}
                             << "--fps";
    QTest::newRow("bad rest pose") << QStringList{"segment", bar,           "--clusters", "4",  "--h",
                                                  "0.1",     "--rest-pose", "x",          "-o", "x.json"}
                                   << "--rest-pose";
    QTest::newRow("no output") << QStringList{"segment", bar, "--clusters", "4", "--h", "0.1"} << "-o labels.json";
    QTest::newRow("bad output") << QStringList{"segment", bar, "--clusters", "4", "--h", "0.1", "-o", "x.png"}
                                << ".json, .csv or .gltf";
    QTest::newRow("unknown option") << QStringList{"segment",      bar,  "--clusters", "4", "--h", "0.1",
                                                   "--frobnicate", "-o", "x.json"}
                                    << "frobnicate";
}

void TestSegmentVerb::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
}

void TestSegmentVerb::badInputsExitWithOne_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QStringList tail = {"--clusters", "3", "--h", "0.1", "-o", m_dir.filePath("bad.json")};
    QTest::newRow("missing folder") << (QStringList{"segment", "/nonexistent/poses"} + tail) << "/nonexistent/poses";
    QTest::newRow("mismatched faces") << (QStringList{"segment", animation("mismatched_faces")} + tail)
                                      << "mesh_0002.obj: face 5 is (2, 8, 9) but the first pose has (2, 8, 7)";
    QTest::newRow("mismatched vertices") << (QStringList{"segment", animation("mismatched_vertices/mesh_%04d.obj")} +
                                             tail)
                                         << "mesh_0001.obj: has 11 vertices";
    QTest::newRow("broken pose") << (QStringList{"segment", animation("broken_pose")} + tail) << "mesh_0001.obj:9:";
    QTest::newRow("rest pose out of range")
        << (QStringList{"segment", animation("bar"), "--rest-pose", "3"} + tail) << "the rest pose 3 does not exist";
    QTest::newRow("one pose") << (QStringList{"segment", animation("bar/bar_1.*")} + tail) << "needs at least 2";
    QTest::newRow("acceleration needs three")
        << (QStringList{"segment", animation("bar/bar_?.obj"), "--feature", "acceleration"} + tail)
        << "needs at least 3";
}

void TestSegmentVerb::badInputsExitWithOne()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 1, message);
}

void TestSegmentVerb::writesDocumentedJson()
{
    const QString out = m_dir.filePath("bar.json");
    const Run run =
        runTrimlab({"segment", animation("bar"), "--clusters", "2", "--h", "0.2", "--mode", "variable", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(run.out.contains("segments: ") && run.out.contains("times (ms): load ") && run.out.contains("features ") &&
                 run.out.contains("partitions ") && run.out.contains("over-segmentation ") &&
                 run.out.contains("cleaning "),
             qPrintable(run.out));
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QJsonParseError error;
    const QJsonObject o = QJsonDocument::fromJson(file.readAll(), &error).object();
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
    for (const char* field : {"format",
                              "version",
                              "source",
                              "vertex_count",
                              "face_count",
                              "pose_count",
                              "rest_pose",
                              "feature",
                              "reference",
                              "method",
                              "clusters",
                              "mode",
                              "h",
                              "partitioned_poses",
                              "clusters_per_pose",
                              "over_segment_count",
                              "segment_count",
                              "segments",
                              "times_ms",
                              "labels",
                              "variable"})
        QVERIFY2(o.contains(field), field);
    QCOMPARE(o["vertex_count"].toInt(), 10);
    QCOMPARE(o["pose_count"].toInt(), 3);
    QCOMPARE(o["clusters"].toInt(), 2);
    QCOMPARE(o["h"].toDouble(), 0.2);
    QCOMPARE(o["labels"].toArray().size(), 10);
    QCOMPARE(o["segments"].toArray().size(), o["segment_count"].toInt());
    QVERIFY(run.out.contains(QStringLiteral("segments: %1 ").arg(o["segment_count"].toInt())));
    QCOMPARE(o["variable"].toArray().size(), 2);
    // The folded half (x > 2) moves, the rest does not: vertices 0 and 4 end up apart.
    QVERIFY(o["labels"].toArray()[0].toInt() != o["labels"].toArray()[4].toInt());
}

void TestSegmentVerb::writesCsvAndGltf()
{
    const QString csv = m_dir.filePath("bar.csv");
    Run run = runTrimlab({"segment", animation("bar/bar_%d.obj"), "--clusters", "2", "--h", "0", "--method",
                          "hierarchical", "--reference", "previous", "-o", csv});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).trimmed().split('\n');
    QCOMPARE(lines.size(), 11);
    QCOMPARE(lines[0], QString("vertex,label"));
    QVERIFY(lines[1].startsWith("0,"));
    const QString gltf = m_dir.filePath("bar.gltf");
    run = runTrimlab({"segment", animation("bar"), "--clusters", "2", "--h", "0.5", "-o", gltf});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QFile gltfFile(gltf);
    QVERIFY(gltfFile.open(QIODevice::ReadOnly));
    const QJsonObject o = QJsonDocument::fromJson(gltfFile.readAll()).object();
    const QJsonObject attributes =
        o["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject()["attributes"].toObject();
    QVERIFY(attributes.contains("_SEGMENT") && attributes.contains("COLOR_0") && attributes.contains("POSITION"));
}

void TestSegmentVerb::segmentsGltfAnimation()
{
    const QString out = m_dir.filePath("skinned.json");
    const Run run = runTrimlab({"segment", animation("skinned_bar.gltf"), "--clusters", "2", "--h", "0", "--fps", "4",
                                "--threads", "1", "-o", out});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject o = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(o["pose_count"].toInt(), 5); // t = 0, 0.25, 0.5, 0.75, 1
    QCOMPARE(o["vertex_count"].toInt(), 6);
}

QTEST_GUILESS_MAIN(TestSegmentVerb)
#include "tst_segment_verb.moc"
