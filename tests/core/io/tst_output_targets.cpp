// What an output may replace (core/io/output_target.h, atomic_write.h): only regular
// files. A FIFO, a socket, a device or a folder at the output path is refused before
// anything is created; a link is followed and its target written; the replaced file's mode
// is kept and a new file follows the umask; a name at the folder's file-name limit still
// gets its temporary; and a file-size limit ends the save with a one-line error, the old
// file intact and no temporary left. All files are made in the test.
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/io/output_paths.h"
#include "core/io/output_target.h"
#include "core/io/stale_temporaries.h"

#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using namespace trimlab;
namespace fs = std::filesystem;

namespace {

void writeText(const fs::path& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::size_t entriesIn(const fs::path& folder)
{
    return std::size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

mode_t modeOf(const fs::path& path)
{
    struct stat status {};
    ::stat(path.c_str(), &status);
    return status.st_mode & 07777;
}

// A bound AF_UNIX socket at `path` (kept open while the test runs).
int bindSocket(const fs::path& path)
{
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
    if (fd >= 0 && ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

// The message writeFileAtomically throws for `path`, or "" when it wrote.
std::string writeError(const fs::path& path, const std::string& bytes)
{
    try {
        io::writeFileAtomically(path, bytes);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

} // namespace

class TestOutputTargets : public QObject {
    Q_OBJECT
private slots:
    void nonRegularFilesAreRefusedBeforeAnyWork();
    void linksAreFollowedToTheirTarget();
    void modesAreKeptOrFollowTheUmask();
    void longNamesGetTemporariesThatFit();
    void fileSizeLimitLeavesTheOldFile();
};

void TestOutputTargets::nonRegularFilesAreRefusedBeforeAnyWork()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const fs::path root = dir.path().toStdString();
    const fs::path fifo = root / "pipe.png";
    QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
    const fs::path socket = root / "s.png";
    const int socketFd = bindSocket(socket);
    QVERIFY(socketFd >= 0);
    fs::create_directory(root / "folder.png");
    struct Case {
        fs::path path;
        std::string kind;
    };
    const Case cases[] = {{fifo, "is a FIFO (named pipe), not a regular file"},
                          {socket, "is a socket, not a regular file"},
                          {"/dev/null", "is a character device, not a regular file"},
                          {root / "folder.png", "is a folder; give a file name"}};
    const std::size_t before = entriesIn(root);
    for (const Case& c : cases) {
        const std::optional<std::string> checked = io::checkOutputPaths({{"-o", c.path.string()}});
        QVERIFY2(checked && checked->find(c.kind) != std::string::npos, c.path.c_str());
        const std::string thrown = writeError(c.path, "data");
        QVERIFY2(thrown.find(c.kind) != std::string::npos, thrown.c_str());
    }
    // Nothing was replaced, and no temporary was left.
    QCOMPARE(entriesIn(root), before);
    QVERIFY(fs::is_fifo(fifo));
    QVERIFY(fs::is_socket(socket));
    QVERIFY(fs::is_character_file("/dev/null"));
    ::close(socketFd);
}

void TestOutputTargets::linksAreFollowedToTheirTarget()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const fs::path root = dir.path().toStdString();
    fs::create_directory(root / "real");
    writeText(root / "real" / "out.obj", "old");
    fs::create_symlink("real/out.obj", root / "latest.obj");
    io::writeFileAtomically(root / "latest.obj", "new");
    QVERIFY(fs::is_symlink(root / "latest.obj"));
    QCOMPARE(readText(root / "real" / "out.obj"), std::string("new"));
    // A dangling link creates its target; a chain of links ends at the last one's target.
    fs::create_symlink("real/fresh.obj", root / "dangling.obj");
    fs::create_symlink("dangling.obj", root / "chain.obj");
    io::writeFileAtomically(root / "chain.obj", "fresh");
    QVERIFY(fs::is_symlink(root / "dangling.obj"));
    QCOMPARE(readText(root / "real" / "fresh.obj"), std::string("fresh"));
    // A loop is refused, by the up-front check and by the writer.
    fs::create_symlink("loop-b.obj", root / "loop-a.obj");
    fs::create_symlink("loop-a.obj", root / "loop-b.obj");
    const std::string thrown = writeError(root / "loop-a.obj", "x");
    QVERIFY2(thrown.find("loop of symbolic links") != std::string::npos, thrown.c_str());
    QVERIFY(io::checkOutputPaths({{"-o", (root / "loop-a.obj").string()}}).has_value());
    // Two outputs that reach one file through a link are one file.
    QVERIFY(
        io::checkOutputPaths({{"-o", (root / "latest.obj").string()}, {"--json", (root / "real" / "out.obj").string()}})
            .has_value());
    // A link to a FIFO is refused like the FIFO.
    QCOMPARE(::mkfifo((root / "pipe").c_str(), 0600), 0);
    fs::create_symlink("pipe", root / "to-pipe.png");
    const std::string pipeError = writeError(root / "to-pipe.png", "x");
    QVERIFY2(pipeError.find("a link to") != std::string::npos && pipeError.find("FIFO") != std::string::npos,
             pipeError.c_str());
}

void TestOutputTargets::modesAreKeptOrFollowTheUmask()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const fs::path root = dir.path().toStdString();
    const fs::path secret = root / "private.trimlab";
    writeText(secret, "old");
    QCOMPARE(::chmod(secret.c_str(), 0600), 0);
    io::writeFileAtomically(secret, "new");
    QCOMPARE(modeOf(secret), mode_t(0600));
    const fs::path shared = root / "shared.trimlab";
    writeText(shared, "old");
    QCOMPARE(::chmod(shared.c_str(), 0664), 0);
    io::writeFileAtomically(shared, "new");
    QCOMPARE(modeOf(shared), mode_t(0664));
    const mode_t previous = ::umask(027);
    io::writeFileAtomically(root / "new.trimlab", "new");
    ::umask(previous);
    QCOMPARE(modeOf(root / "new.trimlab"), mode_t(0640));
}

void TestOutputTargets::longNamesGetTemporariesThatFit()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const fs::path root = dir.path().toStdString();
    const std::size_t limit = io::fileNameLimit(root);
    // The longest legal name, ending in a multi-byte character cut by the shortening.
    std::string name(limit - 6, 'a');
    name += "\xc3\xa9.obj"; // "é.obj"
    QCOMPARE(name.size(), limit);
    const fs::path target = root / name;
    io::writeFileAtomically(target, "first");
    io::writeFileAtomically(target, "second");
    QCOMPARE(readText(target), std::string("second"));
    QCOMPARE(entriesIn(root), std::size_t(1));
    const std::string prefix = io::temporaryPrefix(target, limit);
    QVERIFY(prefix.size() + io::kTemporarySuffixLength <= limit);
    QVERIFY(io::isAtomicWriteTemporaryOf(target, root / (prefix + "abc123")));
    // Another long name with the same beginning has temporaries of its own.
    const fs::path sibling = root / (std::string(limit - 6, 'a') + "x.obj");
    QVERIFY(io::temporaryPrefix(sibling, limit) != prefix);
    QVERIFY(!io::isAtomicWriteTemporaryOf(sibling, root / (prefix + "abc123")));
    // Short names keep the plain form.
    QCOMPARE(io::temporaryPrefix(root / "a.obj", limit), std::string("a.obj.tmp-"));
}

void TestOutputTargets::fileSizeLimitLeavesTheOldFile()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const fs::path root = dir.path().toStdString();
    const fs::path target = root / "out.obj";
    writeText(target, "the earlier export");
    rlimit saved{};
    QCOMPARE(::getrlimit(RLIMIT_FSIZE, &saved), 0);
    // Without SIG_IGN the kernel would end this process with SIGXFSZ instead of EFBIG.
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved;
    limited.rlim_cur = 4096;
    QCOMPARE(::setrlimit(RLIMIT_FSIZE, &limited), 0);
    const std::string thrown = writeError(target, std::string(100000, 'v'));
    ::setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);
    QVERIFY2(thrown.find("File too large") != std::string::npos && thrown.find("ulimit -f") != std::string::npos &&
                 thrown.find("the existing file is unchanged") != std::string::npos,
             thrown.c_str());
    QCOMPARE(thrown.find('\n'), std::string::npos);
    QCOMPARE(readText(target), std::string("the earlier export"));
    QCOMPARE(entriesIn(root), std::size_t(1));
}

QTEST_GUILESS_MAIN(TestOutputTargets)
#include "tst_output_targets.moc"
