// Files that are not what their names claim, made in the test: every loader refuses a
// folder, a named pipe (FIFO), a device, a socket and a loop of symbolic links up front,
// with a one-line error naming the file and what it is, and never blocks (a FIFO with no
// writer blocked a plain open) or reads without bound (/dev/zero never ended). glTF files
// read external buffers only from inside their own folder: "..", absolute paths, URI
// schemes and symbolic links that leave the folder are refused with the URI named.
#include "core/animation/animation_loader.h"
#include "core/catalog/scene_source.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"
#include "core/skeleton/skeleton_json.h"
#include "core/surface/cage_obj.h"
#include "core/timeline/project_file.h"
#include "core/timeline/stroke_script.h"

#include <QTemporaryDir>
#include <QtTest>

#include <functional>
#include <fstream>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using namespace trimlab;

namespace {

using Loader = std::function<void(const std::string&)>;

/// The loaders a user reaches through File ▸ Open, Open Animation, replay scripts, the
/// skeleton panel and the command line, each with the extension it is chosen by.
struct NamedLoader {
    const char* name;
    const char* extension;
    Loader load;
};

std::vector<NamedLoader> loaders()
{
    return {
        {"mesh", ".obj", [](const std::string& p) { (void)loadMesh(p); }},
        {"mesh via loadScene", ".stl", [](const std::string& p) { (void)loadScene(p); }},
        {"glTF mesh", ".glb", [](const std::string& p) { (void)loadMesh(p); }},
        {"NURBS", ".nurbs.json", [](const std::string& p) { (void)loadScene(p); }},
        {"cage", ".obj", [](const std::string& p) { (void)loadCageObj(p); }},
        {"project", ".trimlab", [](const std::string& p) { (void)timeline::loadProject(p); }},
        {"stroke script", ".json", [](const std::string& p) { (void)timeline::loadStrokeScript(p); }},
        {"skeleton", ".json", [](const std::string& p) { (void)loadSkeletonJson(p); }},
        {"glTF animation", ".glb", [](const std::string& p) { (void)loadAnimation(p); }},
    };
}

/// The error a load gave, or "" when it did not throw.
std::string errorOf(const Loader& load, const std::string& path)
{
    try {
        load(path);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

/// A listening Unix socket at `path` (closed when the test ends; the node stays).
bool makeSocket(const std::string& path)
{
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (fd < 0 || path.size() >= sizeof(address.sun_path))
        return false;
    std::copy(path.begin(), path.end(), address.sun_path);
    const bool bound = ::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) == 0;
    ::close(fd);
    return bound;
}

/// A glTF asset with one triangle whose buffer is the external file `uri`.
std::string gltfWithBuffer(const std::string& uri)
{
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"byteLength":36,"uri":")" +
           uri + R"("}]})";
}

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

/// 36 bytes: the triangle (0,0,0), (1,0,0), (0,1,0) as floats.
std::string triangleBuffer()
{
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(positions), sizeof(positions));
}

} // namespace

class TestHostileFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void refusesWhatIsNoRegularFile_data();
    void refusesWhatIsNoRegularFile();
    void readsTheBufferInsideTheFolder();
    void refusesReferencesThatLeaveTheFolder_data();
    void refusesReferencesThatLeaveTheFolder();

private:
    QTemporaryDir m_dir;
};

void TestHostileFiles::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

void TestHostileFiles::refusesWhatIsNoRegularFile_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("expected");
    for (const char* kind : {"folder", "fifo", "device", "socket", "loop"}) {
        const QString expected = QString::fromLatin1(kind) == "folder"   ? "is a folder"
                                 : QString::fromLatin1(kind) == "fifo"   ? "is a named pipe (FIFO)"
                                 : QString::fromLatin1(kind) == "device" ? "is a device"
                                 : QString::fromLatin1(kind) == "socket" ? "is a socket"
                                                                         : "is a loop of symbolic links";
        QTest::newRow(kind) << QString::fromLatin1(kind) << expected;
    }
}

void TestHostileFiles::refusesWhatIsNoRegularFile()
{
    QFETCH(QString, kind);
    QFETCH(QString, expected);
    for (const NamedLoader& loader : loaders()) {
        const std::string path = m_dir.filePath(kind + "-" + loader.name + loader.extension).toStdString();
        bool made = false;
        if (kind == "folder")
            made = ::mkdir(path.c_str(), 0700) == 0;
        else if (kind == "fifo")
            made = ::mkfifo(path.c_str(), 0600) == 0;
        else if (kind == "device")
            made = ::symlink("/dev/zero", path.c_str()) == 0;
        else if (kind == "socket")
            made = makeSocket(path);
        else // two links that point at each other
            made = ::symlink((path + ".other").c_str(), path.c_str()) == 0 &&
                   ::symlink(path.c_str(), (path + ".other").c_str()) == 0;
        QVERIFY2(made, path.c_str());
        const std::string message = errorOf(loader.load, path);
        QVERIFY2(!message.empty(), qPrintable(QString("%1: the %2 loader read it").arg(kind, loader.name)));
        QVERIFY2(
            message.find(path) != std::string::npos,
            qPrintable(QString("%1 loader: the message does not name the file: %2").arg(loader.name, message.c_str())));
        QVERIFY2(QString::fromStdString(message).contains(expected),
                 qPrintable(QString("%1 loader: %2").arg(loader.name, message.c_str())));
        QVERIFY2(message.find('\n') == std::string::npos, message.c_str());
    }
}

// The positive case: a buffer beside the .gltf (and in a subfolder) is read.
void TestHostileFiles::readsTheBufferInsideTheFolder()
{
    QDir(m_dir.path()).mkpath("inside/sub");
    writeFile(m_dir.filePath("inside/sub/tri.bin").toStdString(), triangleBuffer());
    writeFile(m_dir.filePath("inside/tri.gltf").toStdString(), gltfWithBuffer("sub/tri.bin"));
    const TriangleMesh mesh = loadMesh(m_dir.filePath("inside/tri.gltf").toStdString());
    QCOMPARE(mesh.triangles.size(), std::size_t(1));
    QCOMPARE(mesh.positions.size(), std::size_t(3));
}

void TestHostileFiles::refusesReferencesThatLeaveTheFolder_data()
{
    QTest::addColumn<QString>("uri");
    QTest::addColumn<QString>("named"); // the URI as the message names it (percent-decoded)
    QTest::addColumn<QString>("expected");
    QTest::newRow("parent") << "../secret.bin"
                            << "../secret.bin"
                            << "outside the asset's folder";
    QTest::newRow("deeper parent") << "sub/../../secret.bin"
                                   << "sub/../../secret.bin"
                                   << "outside the asset's folder";
    QTest::newRow("percent-encoded parent") << "%2e%2e/secret.bin"
                                            << "../secret.bin"
                                            << "outside the asset's folder";
    QTest::newRow("absolute") << "/etc/passwd"
                              << "/etc/passwd"
                              << "is an absolute path";
    QTest::newRow("file scheme") << "file:///etc/passwd"
                                 << "file:///etc/passwd"
                                 << "URI scheme 'file:'";
    QTest::newRow("http scheme") << "http://example.com/secret.bin"
                                 << "http://example.com/secret.bin"
                                 << "URI scheme 'http:'";
    QTest::newRow("link out") << "escape.bin"
                              << "escape.bin"
                              << "outside the asset's folder";
}

void TestHostileFiles::refusesReferencesThatLeaveTheFolder()
{
    QFETCH(QString, uri);
    QFETCH(QString, named);
    QFETCH(QString, expected);
    const QString folder = m_dir.filePath("asset-" + QString(QTest::currentDataTag()).replace(' ', '-'));
    QDir().mkpath(folder + "/sub");
    // A readable buffer outside the folder, where each URI would lead.
    writeFile(m_dir.filePath("secret.bin").toStdString(), triangleBuffer());
    if (uri == "escape.bin")
        QVERIFY(::symlink(m_dir.filePath("secret.bin").toUtf8().constData(),
                          (folder + "/escape.bin").toUtf8().constData()) == 0);
    const std::string path = (folder + "/tri.gltf").toStdString();
    writeFile(path, gltfWithBuffer(uri.toStdString()));
    const std::string message = errorOf([](const std::string& p) { (void)loadMesh(p); }, path);
    QVERIFY2(!message.empty(), qPrintable("read the buffer " + uri));
    QVERIFY2(message.find(path) != std::string::npos, message.c_str());
    QVERIFY2(QString::fromStdString(message).contains("'" + named + "'"), message.c_str());
    QVERIFY2(QString::fromStdString(message).contains(expected), message.c_str());
}

QTEST_GUILESS_MAIN(TestHostileFiles)
#include "tst_hostile_files.moc"
