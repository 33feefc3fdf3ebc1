// The batch verbs against a hostile file system and hostile files, run as a batch farm
// runs them (a child process): an output that is a FIFO, a device or a folder is refused
// before any work; a file-size limit (ulimit -f) ends the verb with one line, the earlier
// output intact and no temporary left, instead of SIGXFSZ killing it; a placement that
// overflows single precision is refused naming the object; and text from a file reaches
// the terminal escaped (no escape sequence from the file is printed as is).
#include "run_trimlab.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>
#include <sys/stat.h>

using trimlab::test::Run;
using trimlab::test::runTrimlab;

namespace {

void writeBytes(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

QByteArray readBytes(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Runs trimlab with RLIMIT_FSIZE set to `bytes` in the child only.
Run runWithFileSizeLimit(const QStringList& arguments, rlim_t bytes)
{
    QProcess process;
    process.setChildProcessModifier([bytes] {
        rlimit limit{bytes, bytes};
        ::setrlimit(RLIMIT_FSIZE, &limit);
    });
    process.start(trimlab::test::trimlabExecutable(), arguments);
    Run run;
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    return run;
}

} // namespace

class TestHostileOutputs : public QObject {
    Q_OBJECT
private slots:
    void nonRegularOutputsAreRefusedFirst_data();
    void nonRegularOutputsAreRefusedFirst();
    void fileSizeLimitEndsWithOneLine();
    void overflowingPlacementsAreRefused();
    void fileTextReachesTheTerminalEscaped();
};

void TestHostileOutputs::nonRegularOutputsAreRefusedFirst_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("message");
    QTest::newRow("FIFO") << "fifo"
                          << "is a FIFO (named pipe), not a regular file";
    QTest::newRow("link to a device") << "device"
                                      << "(a link to /dev/null) is a character device, not a regular file";
    QTest::newRow("folder") << "folder"
                            << "is a folder; give a file name";
}

void TestHostileOutputs::nonRegularOutputsAreRefusedFirst()
{
    QFETCH(QString, kind);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QString output = dir.filePath(QStringLiteral("out.obj"));
    if (kind == QLatin1String("fifo"))
        QCOMPARE(::mkfifo(QFile::encodeName(output).constData(), 0600), 0);
    else if (kind == QLatin1String("device"))
        QVERIFY(QFile::link(QStringLiteral("/dev/null"), output));
    else
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("out.obj")));
    // A FIFO opened for writing would block this run until the test's time limit.
    TRIMLAB_VERIFY_ONE_LINE_ERROR(
        runTrimlab({"trim", "demo:pushed-sphere", "--rule", "alternating-border", "-o", output}, 60000), 2, message);
    // What was there is still there, and nothing was added beside it.
    QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries | QDir::System).size(), 1);
}

void TestHostileOutputs::fileSizeLimitEndsWithOneLine()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString output = dir.filePath(QStringLiteral("trimmed.obj"));
    writeBytes(output, "# the earlier export\n");
    const Run run =
        runWithFileSizeLimit({"trim", "demo:pushed-sphere", "--rule", "alternating-border", "-o", output}, 8192);
    TRIMLAB_VERIFY_ONE_LINE_ERROR(run, 1, QStringLiteral("File too large"));
    QVERIFY2(run.err.contains(QLatin1String("the existing file is unchanged")), qPrintable(run.err));
    QCOMPARE(readBytes(output), QByteArray("# the earlier export\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::Files).size(), 1);
}

void TestHostileOutputs::overflowingPlacementsAreRefused()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const Run info = runTrimlab({"info", "demo:sphere", "--object-transform", "0=0,0,1e39"});
    TRIMLAB_VERIFY_ONE_LINE_ERROR(info, 2, QStringLiteral("--object-transform 0: object 0 ("));
    QVERIFY2(info.err.contains(QLatin1String("its model matrix entry [3][2] is 1e+39, beyond single precision")),
             qPrintable(info.err));
    TRIMLAB_VERIFY_ONE_LINE_ERROR(runTrimlab({"trim", "demo:sphere", "--rule", "nonzero", "--object-transform",
                                              "0=0,0,0,0,0,0,1e39", "-o", dir.filePath("x.obj")}),
                                  2, QStringLiteral("beyond single precision"));
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("x.obj"))));
}

void TestHostileOutputs::fileTextReachesTheTerminalEscaped()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // A token that would turn the terminal red and set its title.
    const QString path = dir.filePath(QStringLiteral("evil.obj"));
    writeBytes(path, "v 0 0 0\nv 1 0 0\nv 0 1 \x1b[31m\x1b]0;owned\x07\nf 1 2 3\n");
    const Run run = runTrimlab({"info", path});
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(!run.err.contains(QChar(0x1b)) && !run.err.contains(QChar(0x07)),
             qPrintable(run.err.toUtf8().toPercentEncoding(" :'/,.()")));
    QVERIFY2(run.err.contains(QLatin1String("\\x1b[31m\\x1b]0;owned\\x07")), qPrintable(run.err));
}

QTEST_GUILESS_MAIN(TestHostileOutputs)
#include "tst_hostile_outputs.moc"
