// `trimlab bench` as a developer runs it: on the pushed-sphere demo at a small size, the
// table has one row per method of this build, the JSON file holds the same fields, every
// method agrees with the CPU reference (>= 99.9 %), ratios are numbers or "n/a", and bad
// arguments or missing shared data are reported as documented.
#include "run_trimlab.h"
#include "test_paths.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

// A bench run renders every method over several views: allow it 5 minutes.
Run runBench(const QStringList& arguments)
{
    return runTrimlab(arguments, 300000);
}

bool glRequired()
{
    return qEnvironmentVariable("TRIMLAB_REQUIRE_GL") == QLatin1String("1");
}

/// The table's data rows (those that start with the scene name).
QStringList tableRows(const QString& out, const QString& scene)
{
    QStringList rows;
    for (const QString& line : out.split(QLatin1Char('\n')))
        if (line.startsWith(scene + QLatin1Char(' ')))
            rows << line;
    return rows;
}

const QStringList kMeasuredFields = {"msPerFrame",       "timeSource",          "wallMsMedian",
                                     "geometryPasses",   "megabytes",           "fragmentsInSpan",
                                     "fragmentsStored",  "fragmentsLost",       "overflowPixels",
                                     "unresolvedPixels", "agreementPercent",    "worstViewAgreementPercent",
                                     "comparedPixels",   "excludedPercent",     "ratioToF2B",
                                     "ratioToABLL",      "pipelinedMsPerFrame", "pipelinedToGpu"};

} // namespace

class TestBenchVerb : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void demoSceneAgreesForEveryMethod();
    void restrictedMethodsGiveNotAvailableRatios();
    void badArgumentsExitWithTwo_data();
    void badArgumentsExitWithTwo();
    void missingSharedDataSkipsTheScene();
    void animationSceneTimesSkinningBothWays();
    void csgGoalSceneSkipsPeelingAndAgrees();
    void spinLocksOnlyMeasuresTheSpinLock();
    void positionalSourcesMakeOneScene();

private:
    QTemporaryDir m_dir;
    QJsonObject m_report;
    QString m_out;
};

void TestBenchVerb::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const QString json = m_dir.filePath(QStringLiteral("bench.json"));
    const Run run =
        runBench({"bench", "--scenes", "demo:pushed-sphere", "--size", "160x120", "--repeat", "1", "--json", json});
    if (run.exitCode != 0 && run.err.contains(QStringLiteral("OpenGL")) && !glRequired())
        QSKIP(qPrintable("no OpenGL for the bench: " + run.err));
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    m_out = run.out;
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QJsonParseError error;
    m_report = QJsonDocument::fromJson(file.readAll(), &error).object();
    QVERIFY2(error.error == QJsonParseError::NoError, qPrintable(error.errorString()));
}

void TestBenchVerb::demoSceneAgreesForEveryMethod()
{
    QVERIFY2(m_out.contains(QStringLiteral("OpenGL: ")) && m_out.contains(QStringLiteral("CPU threads: ")),
             qPrintable(m_out));
    const QJsonObject header = m_report.value("header").toObject();
    QCOMPARE(header.value("sizes").toArray(), QJsonArray{QStringLiteral("160x120")});
    QCOMPARE(header.value("repeat").toInt(), 1);
    QVERIFY(!header.value("openGl").toString().isEmpty());
    const QJsonArray methods = header.value("methods").toArray();
    QVERIFY(!methods.isEmpty());
    const QJsonArray results = m_report.value("results").toArray();
    QCOMPARE(results.size(), methods.size());
    const QStringList rows = tableRows(m_out, QStringLiteral("demo:pushed-sphere"));
    QCOMPARE(rows.size(), methods.size());
    for (qsizetype i = 0; i < results.size(); ++i) {
        const QJsonObject result = results[i].toObject();
        const QString method = result.value("method").toString();
        QCOMPARE(method, methods[i].toString());
        QVERIFY2(rows[i].contains(method), qPrintable(rows[i]));
        QCOMPARE(result.value("status").toString(), QStringLiteral("ok"));
        for (const QString& field : kMeasuredFields)
            QVERIFY2(result.contains(field), qPrintable(method + ": no " + field));
        QVERIFY2(result.value("agreementPercent").toDouble() >= 99.9, qPrintable(method));
        QVERIFY2(result.value("worstViewAgreementPercent").toDouble() >= 99.9, qPrintable(method));
        QVERIFY2(result.value("comparedPixels").toInt() > 1000, qPrintable(method)); // not vacuous
        QVERIFY(result.value("excludedPercent").toDouble() <= 5.0);
        QVERIFY(result.value("geometryPasses").toInt() >= 1);
        QVERIFY(result.value("fragmentsInSpan").toDouble() > 0.0);
        QVERIFY2(result.value("pipelinedMsPerFrame").toDouble() > 0.0, qPrintable(method)); // measured
        QCOMPARE(result.value("views").toInt(), 8);
        const QString source = result.value("timeSource").toString();
        QVERIFY(source == QLatin1String("GPU") || source == QLatin1String("wall"));
        // The k⁺-buffer family reports its critical section; no other method has one.
        const bool locking = method.startsWith(QStringLiteral("kplus"));
        const QString lock = result.value("lock").toString();
        QVERIFY2(locking ? (lock == QLatin1String("spin-lock") || lock == QLatin1String("interlock"))
                         : lock == QLatin1String("none"),
                 qPrintable(method + ": lock " + lock));
        QCOMPARE(result.value("interlock").toBool(), lock == QLatin1String("interlock"));
    }
}

// Without F2B and AB_LL in the run there is nothing to compare against: "n/a" and null.
void TestBenchVerb::restrictedMethodsGiveNotAvailableRatios()
{
    const QString json = m_dir.filePath(QStringLiteral("one.json"));
    const Run run = runBench({"bench", "--scenes", "demo:sphere", "--size", "96x64", "--repeat", "1", "--views", "2",
                              "--methods", "kplus-array", "--k", "8", "--json", json});
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    const QStringList rows = tableRows(run.out, QStringLiteral("demo:sphere"));
    QCOMPARE(rows.size(), 1);
    QVERIFY2(rows[0].contains(QStringLiteral("kplus-array")) &&
                 rows[0].contains(QRegularExpression(QStringLiteral("n/a\\s+n/a$"))),
             qPrintable(rows[0]));
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject report = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(report.value("header").toObject().value("k").toInt(), 8);
    const QJsonObject result = report.value("results").toArray().first().toObject();
    QVERIFY(result.value("ratioToF2B").isNull());
    QVERIFY(result.value("ratioToABLL").isNull());
    QCOMPARE(result.value("views").toInt(), 2);
}

void TestBenchVerb::badArgumentsExitWithTwo_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown method") << QStringList{"bench", "--methods", "z-buffer"} << "z-buffer";
    QTest::newRow("unknown scene") << QStringList{"bench", "--scenes", "teapot"} << "teapot";
    QTest::newRow("bad size") << QStringList{"bench", "--size", "160x"} << "--size";
    QTest::newRow("bad repeat") << QStringList{"bench", "--repeat", "0"} << "--repeat";
    QTest::newRow("bad locks") << QStringList{"bench", "--locks", "sometimes"} << "--locks";
    QTest::newRow("bad shared counters") << QStringList{"bench", "--shared-counters", "0"} << "--shared-counters";
    QTest::newRow("rule without sources")
        << QStringList{"bench", "--rule", "nonzero"} << "--rule applies to the scene of the positional sources";
    QTest::newRow("bad object transform")
        << QStringList{"bench", "demo:sphere", "--object-transform", "0=a,b,c"} << "is not a finite number";
}

void TestBenchVerb::badArgumentsExitWithTwo()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const Run run = runBench(arguments);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(QStringLiteral("trimlab: error: ")) && run.err.contains(message), qPrintable(run.err));
}

// The catalog's file scenes need the shared data folder; without it they are skipped
// with a note, and a run with nothing left to measure still succeeds.
void TestBenchVerb::missingSharedDataSkipsTheScene()
{
    const QString json = m_dir.filePath(QStringLiteral("skipped.json"));
    const Run run = runBench({"bench", "--scenes", "bunny-cube-50", "--data", m_dir.filePath("no-such-folder"),
                              "--size", "64x48", "--repeat", "1", "--json", json});
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    QVERIFY2(run.err.contains(QStringLiteral("skipping bunny-cube-50")) && run.err.contains(QStringLiteral("missing")),
             qPrintable(run.err));
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject report = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(report.value("results").toArray().size(), 0);
    QCOMPARE(report.value("skipped").toArray().first().toObject().value("scene").toString(),
             QStringLiteral("bunny-cube-50"));
}

// An animation scene: four skinned models of samba's first 40 poses, each pose timed with
// CPU skinning + upload and with GPU skinning, and the GPU's positions read back against
// the CPU's (a row per model; the run fails beyond 1e-5 of the diagonal). Without the
// shared data the scene is skipped like a file scene.
void TestBenchVerb::animationSceneTimesSkinningBothWays()
{
    const Run skipped = runBench({"bench", "--scenes", "skinning:samba", "--data", m_dir.filePath("no-such-folder")});
    QVERIFY2(skipped.exitCode == 0 && skipped.err.contains(QStringLiteral("skipping skinning:samba")),
             qPrintable(skipped.out + skipped.err));
    if (!QFileInfo::exists(QString::fromStdString(trimlab::test::sharedDataPath("anim/samba").string())))
        QSKIP("../shared/data/anim/samba is missing");
    const Run run = runBench({"bench", "--scenes", "skinning:samba", "--repeat", "1"});
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    const QRegularExpression row(QStringLiteral(
        R"(^skinning:samba\s+9971\s+20\s+40\s+(LBS|DQS)\s+(pose-to-pose|rest-to-pose)(\s+[0-9.]+){5}\s+([0-9.e+-]+)$)"));
    int rows = 0;
    for (const QString& line : run.out.split(QLatin1Char('\n'))) {
        const QRegularExpressionMatch match = row.match(line.trimmed());
        if (!match.hasMatch())
            continue;
        ++rows;
        QVERIFY2(match.captured(4).toDouble() <= 1e-5, qPrintable(line));
    }
    QVERIFY2(rows == 4, qPrintable(run.out));
}

// The GPU goal scene (docs/gpu-results.md): three CSG operands, 544,302 triangles, a cap.
// The peeling methods cannot walk a pixel's fragments for CSG: they are reported as not
// applicable, which is no failure; the k⁺-buffer agrees with the CPU reference.
void TestBenchVerb::csgGoalSceneSkipsPeelingAndAgrees()
{
    const QString json = m_dir.filePath(QStringLiteral("csg3.json"));
    const Run run = runBench({"bench", "--scenes", "csg3-500k", "--size", "96x72", "--repeat", "1", "--views", "2",
                              "--methods", "kplus-array,peeling-dual", "--locks", "both", "--json", json});
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    QVERIFY2(run.err.contains(QStringLiteral("csg3-500k (544,302 triangles, 3 objects)")), qPrintable(run.err));
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject report = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(report.value("header").toObject().value("locks").toString(), QStringLiteral("both"));
    const QJsonArray results = report.value("results").toArray();
    QVERIFY(results.size() >= 2); // a third cell where the driver has interlock: kplus-array with the spin-lock
    bool sawSpinLock = false;
    for (const QJsonValue& value : results) {
        const QJsonObject result = value.toObject();
        const QString method = result.value("method").toString();
        if (method == QLatin1String("peeling-dual")) {
            QCOMPARE(result.value("status").toString(), QStringLiteral("not-applicable"));
            continue;
        }
        QCOMPARE(method, QStringLiteral("kplus-array"));
        QCOMPARE(result.value("status").toString(), QStringLiteral("ok"));
        QVERIFY2(result.value("agreementPercent").toDouble() >= 99.9, qPrintable(method));
        QVERIFY(result.value("comparedPixels").toInt() > 500);
        sawSpinLock = sawSpinLock || result.value("lock").toString() == QLatin1String("spin-lock");
    }
    QVERIFY2(sawSpinLock, "--locks both always measures the spin-lock");
    QVERIFY2(tableRows(run.out, QStringLiteral("csg3-500k")).join('\n').contains(QStringLiteral("not applicable")),
             qPrintable(run.out));
}

// --locks spin never uses interlock, whatever the driver offers.
void TestBenchVerb::spinLocksOnlyMeasuresTheSpinLock()
{
    const QString json = m_dir.filePath(QStringLiteral("spin.json"));
    const Run run = runBench({"bench", "--scenes", "demo:sphere", "--size", "64x48", "--repeat", "1", "--views", "1",
                              "--methods", "kplus-array,kplus-sbuffer", "--locks", "spin", "--json", json});
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonArray results = QJsonDocument::fromJson(file.readAll()).object().value("results").toArray();
    QCOMPARE(results.size(), 2);
    for (const QJsonValue& value : results)
        QCOMPARE(value.toObject().value("lock").toString(), QStringLiteral("spin-lock"));
}

// `trimlab bench A B --csg ... --rule ...`: the positional sources are one scene, measured
// alone (no catalog scenes) with the given rule and CSG, and checked against the reference.
void TestBenchVerb::positionalSourcesMakeOneScene()
{
    const QString json = m_dir.filePath(QStringLiteral("composed.json"));
    const Run run = runBench({"bench", "demo:pushed-sphere", "demo:sphere", "--object-transform",
                              "1=0,-0.6,0,0,0,0,0.5", "--csg", "0 - 1", "--rule", "nonzero", "--size", "64x48",
                              "--repeat", "1", "--views", "2", "--methods", "abuffer-linked-list", "--json", json});
    QVERIFY2(run.exitCode == 0, qPrintable(run.out + run.err));
    QFile file(json);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject report = QJsonDocument::fromJson(file.readAll()).object();
    const QJsonArray scenes = report.value("header").toObject().value("scenes").toArray();
    QCOMPARE(scenes.size(), 1);
    QCOMPARE(scenes.first().toString(), QStringLiteral("demo:pushed-sphere + demo:sphere"));
    const QJsonArray results = report.value("results").toArray();
    QCOMPARE(results.size(), 1);
    const QJsonObject result = results.first().toObject();
    QCOMPARE(result.value("status").toString(), QStringLiteral("ok"));
    QVERIFY2(result.value("agreementPercent").toDouble() >= 99.9, qPrintable(run.out));
    QVERIFY(result.value("comparedPixels").toInt() > 200);
}

QTEST_GUILESS_MAIN(TestBenchVerb)
#include "tst_bench_verb.moc"
