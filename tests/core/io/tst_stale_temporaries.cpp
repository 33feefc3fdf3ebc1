// Leftovers of killed saves (core/io/stale_temporaries.h): which names count as a
// save's temporary file, and that writeFileAtomically deletes only old temporaries of the
// file it writes — never a fresh one (another process may be saving right now), never one
// of another file, never a file that merely looks similar.
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/stale_temporaries.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>

using namespace trimlab;
using namespace std::chrono_literals;

namespace {

void writeText(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

// Backdates the file's modification time by `age`.
void age(const std::filesystem::path& path, std::chrono::seconds by)
{
    std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now() - by);
}

} // namespace

class TestStaleTemporaries : public QObject {
    Q_OBJECT
private slots:
    void namesOfTemporaries_data();
    void namesOfTemporaries();
    void atomicWriteRemovesOnlyOldTemporariesOfItsFile();
    void removalReportsWhatItDeleted();
};

void TestStaleTemporaries::namesOfTemporaries_data()
{
    QTest::addColumn<QString>("candidate");
    QTest::addColumn<bool>("temporary");
    QTest::newRow("save temporary") << "a.trimlab.tmp-x7k2q9" << true;
    QTest::newRow("digits only") << "a.trimlab.tmp-000000" << true;
    QTest::newRow("upper case") << "a.trimlab.tmp-X7K2Q9" << false;
    QTest::newRow("5 characters") << "a.trimlab.tmp-x7k2q" << false;
    QTest::newRow("7 characters") << "a.trimlab.tmp-x7k2q9z" << false;
    QTest::newRow("other file") << "b.trimlab.tmp-x7k2q9" << false;
    QTest::newRow("prefix of name") << "aa.trimlab.tmp-x7k2q9" << false;
    QTest::newRow("the file itself") << "a.trimlab" << false;
    QTest::newRow("punctuation") << "a.trimlab.tmp-x7k-q9" << false;
}

void TestStaleTemporaries::namesOfTemporaries()
{
    QFETCH(QString, candidate);
    QFETCH(bool, temporary);
    QCOMPARE(io::isAtomicWriteTemporaryOf("/p/a.trimlab", std::filesystem::path("/p") / candidate.toStdString()),
             temporary);
}

void TestStaleTemporaries::atomicWriteRemovesOnlyOldTemporariesOfItsFile()
{
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const std::filesystem::path dir = folder.path().toStdString();
    const std::filesystem::path target = dir / "a.trimlab";
    writeText(target, "old");
    const std::filesystem::path oldTemporary = dir / "a.trimlab.tmp-abc123";
    const std::filesystem::path freshTemporary = dir / "a.trimlab.tmp-def456";
    const std::filesystem::path otherFiles = dir / "b.trimlab.tmp-abc123";
    const std::filesystem::path lookalike = dir / "a.trimlab.tmp-ABC123";
    for (const auto& path : {oldTemporary, freshTemporary, otherFiles, lookalike})
        writeText(path, "partial");
    for (const auto& path : {oldTemporary, otherFiles, lookalike})
        age(path, io::kStaleTemporaryAge + 60s);
    age(freshTemporary, io::kStaleTemporaryAge - 60s);

    io::writeFileAtomically(target, "new");

    QCOMPARE(io::readFileBytes(target, 100), std::string("new"));
    QVERIFY(!std::filesystem::exists(oldTemporary));
    QVERIFY(std::filesystem::exists(freshTemporary));
    QVERIFY(std::filesystem::exists(otherFiles));
    QVERIFY(std::filesystem::exists(lookalike));
    int files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir))
        ++files;
    QCOMPARE(files, 4); // the target, the fresh temporary, b's, the lookalike: nothing new left
}

void TestStaleTemporaries::removalReportsWhatItDeleted()
{
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const std::filesystem::path dir = folder.path().toStdString();
    const std::filesystem::path target = dir / "s.json";
    const std::filesystem::path first = dir / "s.json.tmp-aaaaaa";
    const std::filesystem::path second = dir / "s.json.tmp-bbbbbb";
    writeText(first, "");
    writeText(second, "");
    age(first, 120s);
    age(second, 10s);
    const auto removed = io::removeStaleTemporaries(target, 60s);
    QCOMPARE(removed.size(), std::size_t(1));
    QCOMPARE(removed.front(), first);
    QVERIFY(std::filesystem::exists(second));
    // A folder that does not exist is no error: nothing to clean.
    QVERIFY(io::removeStaleTemporaries(dir / "missing" / "x.trimlab", 0s).empty());
}

QTEST_GUILESS_MAIN(TestStaleTemporaries)
#include "tst_stale_temporaries.moc"
