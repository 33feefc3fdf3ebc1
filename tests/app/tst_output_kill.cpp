// Every kind of file a batch verb writes survives the run being killed: each output
// exists beforehand as a complete file from an earlier run, then the verb is started again
// and killed with SIGKILL at a random moment of its run, 20 times per verb; after every
// kill each output must still be a complete file (the earlier one, or the new one whole),
// never empty or truncated. Outputs go through a temporary file and a rename
// (core/io/atomic_write.h); writing them in place failed this test. Also: output paths
// are checked before any work starts (app/output_paths.h).
#include "run_trimlab.h"
#include "test_paths.h"

#include "core/io/pfm_image.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

constexpr int kKillsPerVerb = 20;

/// How to tell a whole output from a truncated one.
enum class Kind { Png, Pfm, Json, Glb, Csv };

struct Output {
    QString path;
    Kind kind;
};

QByteArray bytesOf(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// "" when `output` is a complete file of its kind, else what is wrong with it.
QString problemOf(const Output& output)
{
    const QByteArray bytes = bytesOf(output.path);
    if (bytes.isEmpty())
        return QStringLiteral("missing or empty");
    switch (output.kind) {
    case Kind::Png:
        return QImage::fromData(bytes, "PNG").isNull() ? QStringLiteral("not a whole PNG") : QString();
    case Kind::Pfm:
        try {
            (void)trimlab::io::readPfm(output.path.toStdString());
        } catch (const std::exception& e) {
            return QString::fromUtf8(e.what());
        }
        return {};
    case Kind::Json: {
        QJsonParseError error;
        (void)QJsonDocument::fromJson(bytes, &error);
        return error.error == QJsonParseError::NoError ? QString()
                                                       : QStringLiteral("not whole JSON: ") + error.errorString();
    }
    case Kind::Csv: {
        // Every row has the header's number of fields, and the file ends with a line break.
        const QList<QByteArray> rows = bytes.split('\n');
        if (!bytes.endsWith('\n') || rows.size() < 3)
            return QStringLiteral("not a whole CSV");
        const qsizetype fields = rows.front().count(',');
        for (qsizetype i = 1; i + 1 < rows.size(); ++i)
            if (rows[i].count(',') != fields)
                return QStringLiteral("CSV row %1 has a different number of fields").arg(i);
        return {};
    }
    case Kind::Glb: {
        if (bytes.size() < 12 || !bytes.startsWith("glTF"))
            return QStringLiteral("no GLB header");
        quint32 length = 0;
        std::memcpy(&length, bytes.constData() + 8, 4);
        return length == quint32(bytes.size())
                   ? QString()
                   : QStringLiteral("GLB declares %1 bytes, file has %2").arg(length).arg(bytes.size());
    }
    }
    return {};
}

QString animation(const QString& relative)
{
    return QString::fromStdString(trimlab::test::testDataPath(("animations/" + relative).toStdString()).string());
}

} // namespace

class TestOutputKill : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void killedVerbsLeaveWholeOutputs_data();
    void killedVerbsLeaveWholeOutputs();
    void outputPathsAreCheckedFirst_data();
    void outputPathsAreCheckedFirst();

private:
    QTemporaryDir m_dir;
};

void TestOutputKill::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

void TestOutputKill::killedVerbsLeaveWholeOutputs_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QStringList>("paths");
    QTest::addColumn<QList<int>>("kinds");
    const QString d = m_dir.path() + QLatin1Char('/');
    QTest::newRow("render -o --depth --ids")
        << QStringList{"render",  "demo:pushed-sphere", "--size", "480x360",      "-o", d + "r.png",
                       "--depth", d + "r.pfm",          "--ids",  d + "r-ids.png"}
        << QStringList{d + "r.png", d + "r.pfm", d + "r-ids.png"}
        << QList<int>{int(Kind::Png), int(Kind::Pfm), int(Kind::Png)};
    QTest::newRow("segment -o .json") << QStringList{"segment", animation("bar"), "--clusters", "2", "--h", "0.2",
                                                     "-o",      d + "s.json"}
                                      << QStringList{d + "s.json"} << QList<int>{int(Kind::Json)};
    QTest::newRow("segment -o .csv") << QStringList{"segment", animation("bar"), "--clusters", "2", "--h", "0.2",
                                                    "-o",      d + "s.csv"}
                                     << QStringList{d + "s.csv"} << QList<int>{int(Kind::Csv)};
    QTest::newRow("segment -o .gltf") << QStringList{"segment", animation("bar"), "--clusters", "2", "--h", "0.2",
                                                     "-o",      d + "s.gltf"}
                                      << QStringList{d + "s.gltf"} << QList<int>{int(Kind::Json)};
    QTest::newRow("skin -o .glb") << QStringList{"skin", animation("bar"), "--bones", "2", "--method", "dqs",
                                                 "-o",   d + "k.glb"}
                                  << QStringList{d + "k.glb"} << QList<int>{int(Kind::Glb)};
    QTest::newRow("skeleton -o --json") << QStringList{"skeleton",  "demo:sphere", "-o",
                                                       d + "t.glb", "--json",      d + "t.json"}
                                        << QStringList{d + "t.glb", d + "t.json"}
                                        << QList<int>{int(Kind::Glb), int(Kind::Json)};
    QTest::newRow("bench --json") << QStringList{"bench",       "--scenes", "demo:sphere", "--size", "96x64",
                                                 "--views",     "1",        "--repeat",    "1",      "--methods",
                                                 "kplus-array", "--json",   d + "b.json"}
                                  << QStringList{d + "b.json"} << QList<int>{int(Kind::Json)};
}

void TestOutputKill::killedVerbsLeaveWholeOutputs()
{
    QFETCH(QStringList, arguments);
    QFETCH(QStringList, paths);
    QFETCH(QList<int>, kinds);
    std::vector<Output> outputs;
    for (qsizetype i = 0; i < paths.size(); ++i)
        outputs.push_back({paths[i], Kind(kinds[i])});

    // A complete run first: the outputs exist, and its time bounds the kill moments.
    QElapsedTimer clock;
    clock.start();
    const Run first = runTrimlab(arguments);
    const qint64 runMs = std::max<qint64>(clock.elapsed(), 50);
    QVERIFY2(first.exitCode == 0, qPrintable(first.err));
    for (const Output& output : outputs)
        QVERIFY2(problemOf(output).isEmpty(), qPrintable(output.path + ": " + problemOf(output)));

    // Fixed seed per verb: a failure names the kill moment and can be repeated.
    QRandomGenerator random(quint32(qHash(QString(QTest::currentDataTag()))));
    int killedBeforeTheEnd = 0;
    for (int kill = 0; kill < kKillsPerVerb; ++kill) {
        const int delayMs = int(random.bounded(quint32(runMs * 12 / 10 + 1)));
        QProcess process;
        process.start(trimlab::test::trimlabExecutable(), arguments);
        QVERIFY(process.waitForStarted());
        QThread::msleep(quint64(delayMs));
        if (process.state() == QProcess::Running)
            ++killedBeforeTheEnd;
        process.kill(); // SIGKILL: no handler runs, no cleanup
        QVERIFY(process.waitForFinished(30000));
        for (const Output& output : outputs) {
            const QString problem = problemOf(output);
            QVERIFY2(problem.isEmpty(), qPrintable(QStringLiteral("%1 after a kill at %2 ms (of a %3 ms run): %4")
                                                       .arg(output.path)
                                                       .arg(delayMs)
                                                       .arg(runMs)
                                                       .arg(problem)));
        }
    }
    // Not vacuous: most kills landed while the verb was still running.
    QVERIFY2(killedBeforeTheEnd >= kKillsPerVerb / 2,
             qPrintable(
                 QStringLiteral("only %1 of %2 kills hit a running verb").arg(killedBeforeTheEnd).arg(kKillsPerVerb)));
}

void TestOutputKill::outputPathsAreCheckedFirst_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    const QString d = m_dir.path() + QLatin1Char('/');
    QTest::newRow("two outputs on one file")
        << QStringList{"render", "demo:sphere", "-o", d + "same.png", "--ids", d + "./same.png"}
        << "-o and --ids both name";
    QTest::newRow("depth over the image")
        << QStringList{"render", "demo:sphere", "-o", d + "x.png", "--depth", d + "sub/../x.png"} << "both name";
    QTest::newRow("missing folder") << QStringList{"render", "demo:sphere", "-o", d + "no/such/folder/x.png"}
                                    << "the folder " + d + "no/such/folder does not exist";
    QTest::newRow("output is a folder") << QStringList{"render", "demo:sphere", "-o", m_dir.path()} << "is a folder";
    QTest::newRow("skeleton json over glb")
        << QStringList{"skeleton", "demo:sphere", "-o", d + "t2.glb", "--json", d + "t2.glb"} << "both name";
    QTest::newRow("segment into a missing folder")
        << QStringList{"segment", animation("bar"), "--clusters", "2", "--h", "0.2", "-o", d + "none/s.json"}
        << "does not exist";
    QTest::newRow("skin into a missing folder")
        << QStringList{"skin", animation("bar"), "--bones", "2", "--method", "dqs", "-o", d + "none/k.glb"}
        << "does not exist";
    QTest::newRow("bench json into a missing folder")
        << QStringList{"bench", "--scenes", "demo:sphere", "--json", d + "none/b.json"} << "does not exist";
}

// Checked before any work: exit code 2, one line, and nothing written.
void TestOutputKill::outputPathsAreCheckedFirst()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QDir(m_dir.path()).mkpath("sub");
    const QStringList before = QDir(m_dir.path()).entryList(QDir::Files);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab(arguments), 2, message);
    QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files), before);
}

QTEST_GUILESS_MAIN(TestOutputKill)
#include "tst_output_kill.moc"
