// Atomic saves under SIGKILL (docs/reliability.md): a helper process
// (save_kill_helper.cpp) saves two versions of a big project over the same file in a
// loop, as saveProject writes them; the test kills it with SIGKILL at varied moments of
// a save — before the temporary file exists, while it is written or fsync'ed, around the rename — and after
// each kill checks that the file loads and is byte for byte one of the two versions.
// A kill between creating and renaming the temporary file leaves that file behind
// (`<name>.tmp-XXXXXX`); the test checks that each kill leaves at most one, named by that
// pattern, and removes them (TrimLab's own saves remove such files once they are old:
// core.stale_temporaries).
#include "save_kill_project.h"

#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/stale_temporaries.h"

#include <QtTest>

#include <algorithm>
#include <chrono>
#include <filesystem>

using namespace trimlab;

namespace {

// Every file next to `target` except `target` itself; `unexpected` gets those not named
// like a save's temporary file (`<name>.tmp-XXXXXX`).
std::vector<std::filesystem::path> temporaries(const std::filesystem::path& target, std::string& unexpected)
{
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::directory_iterator(target.parent_path())) {
        if (entry.path() == target)
            continue;
        found.push_back(entry.path());
        if (!io::isAtomicWriteTemporaryOf(target, entry.path()))
            unexpected += entry.path().filename().string() + " ";
    }
    return found;
}

// Waits until the helper has announced save `count` ("saving N" lines).
bool waitForSave(QProcess& helper, int count)
{
    QByteArray seen;
    const QByteArray wanted = "saving " + QByteArray::number(count) + "\n";
    while (!seen.contains(wanted)) {
        if (!helper.waitForReadyRead(5000))
            return false;
        seen += helper.readAllStandardOutput();
    }
    return true;
}

} // namespace

class TestSaveKill : public QObject {
    Q_OBJECT

private slots:
    void killedSavesLeaveALoadableProject();
};

void TestSaveKill::killedSavesLeaveALoadableProject()
{
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const std::filesystem::path target = std::filesystem::path(folder.path().toStdString()) / "big.trimlab";
    const std::string versions[2] = {timeline::projectJson(test::saveKillTimeline(0), test::saveKillExtras(0)),
                                     timeline::projectJson(test::saveKillTimeline(1), test::saveKillExtras(1))};
    // The previous file: version 0, saved by this process. Timing the atomic write tells
    // how long one save of the helper takes, so the kill delays can sweep over a whole save.
    timeline::saveProject(test::saveKillTimeline(0), target, test::saveKillExtras(0));
    const auto start = std::chrono::steady_clock::now();
    io::writeFileAtomically(target, versions[0]);
    const auto saveUs = std::max<long long>(
        1000, std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - start).count());
    qInfo("project: %zu bytes; one atomic write takes %lld us", versions[0].size(), saveUs);
    // The helper's two versions, in a folder of their own (the target's must hold only
    // the target and temporaries).
    QTemporaryDir sources;
    QVERIFY(sources.isValid());
    QStringList arguments{QString::fromStdString(target.string())};
    for (int v = 0; v < 2; ++v) {
        const std::filesystem::path file =
            std::filesystem::path(sources.path().toStdString()) / ("v" + std::to_string(v));
        io::writeFileAtomically(file, versions[v]);
        arguments << QString::fromStdString(file.string());
    }

    constexpr int kIterations = 50;
    constexpr auto kBudget = std::chrono::seconds(15);
    const auto begin = std::chrono::steady_clock::now();
    int kills = 0;
    int leftovers = 0;
    int sawVersion[2] = {0, 0};
    for (int i = 0; i < kIterations && std::chrono::steady_clock::now() - begin < kBudget; ++i) {
        QProcess helper;
        helper.start(QStringLiteral(SAVE_KILL_HELPER), arguments);
        QVERIFY2(helper.waitForStarted(5000), qPrintable(helper.errorString()));
        // Aim at save 1, 2 or 3, then wait a delay that sweeps [0, 1.5 × one save):
        // consecutive iterations land at different steps of the save.
        QVERIFY2(waitForSave(helper, 1 + i % 3), "the helper did not start saving");
        const long long delayUs = (std::int64_t(i) * 7919 * saveUs / 50) % (saveUs * 3 / 2);
        QThread::usleep(static_cast<unsigned long>(delayUs));
        helper.kill(); // SIGKILL
        QVERIFY(helper.waitForFinished(5000));
        QCOMPARE(helper.exitStatus(), QProcess::CrashExit);
        ++kills;

        const std::string bytes = io::readFileBytes(target, std::size_t(1) << 30);
        const int version = bytes == versions[0] ? 0 : bytes == versions[1] ? 1 : -1;
        QVERIFY2(version >= 0, qPrintable(QString("after kill %1 (delay %2 us) the file is neither version (%3 bytes)")
                                              .arg(i)
                                              .arg(delayUs)
                                              .arg(bytes.size())));
        ++sawVersion[version];
        if (i % 10 == 0) { // the full load path too (a few MB of JSON: not every time)
            const timeline::Project loaded = timeline::readProject(target);
            QVERIFY(loaded.timeline == test::saveKillTimeline(version));
        }
        std::string unexpected;
        const auto stray = temporaries(target, unexpected);
        QVERIFY2(unexpected.empty(), qPrintable("unexpected files: " + QString::fromStdString(unexpected)));
        QVERIFY2(stray.size() <= 1, qPrintable(QString("kill %1 left %2 temporary files").arg(i).arg(stray.size())));
        leftovers += int(stray.size());
        for (const auto& file : stray) // the documented cleanup: delete <name>.tmp-XXXXXX
            std::filesystem::remove(file);
    }
    qInfo("%d kills in %.1f s: file was version 0 %d times, version 1 %d times; %d kills left a temporary file", kills,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), sawVersion[0], sawVersion[1],
          leftovers);
    QVERIFY2(kills >= 20, "too few kills within the time budget");
    // The sweep must have hit both sides of a rename and the middle of a save.
    QVERIFY2(sawVersion[0] > 0 && sawVersion[1] > 0, "the kills did not fall on both sides of a rename");
    QVERIFY2(leftovers > 0, "no kill fell between creating and renaming the temporary file");
}

QTEST_GUILESS_MAIN(TestSaveKill)
#include "tst_save_kill.moc"
