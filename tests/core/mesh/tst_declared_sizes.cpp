// What a file declares about its own size must agree with what it holds, in files made in
// the test: a binary STL whose triangle count is smaller than its data, PLY bodies with
// data after the last element (ASCII and binary), a PLY property declared twice, and glTF
// offsets and indices that are negative or out of range (scene, node, buffer view,
// accessor), geometry whose every triangle has zero area, and integers at and past the
// 64-bit limits. Each is refused with a
// message naming the file and the value read; before, each loaded (the extra data and the
// negative values silently ignored). A trailing line break is no data and still loads.
#include "core/catalog/scene_source.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_load_error.h"

#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cstring>
#include <fstream>

using namespace trimlab;

namespace {

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

/// A binary STL of a tetrahedron whose header declares `declared` triangles (the data
/// holds 4), followed by `tail`.
std::string binaryStl(std::uint32_t declared, const std::string& tail = {})
{
    const std::array<std::array<float, 3>, 4> v = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const std::array<std::array<int, 3>, 4> faces = {{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
    std::string bytes(80, ' ');
    bytes.append(reinterpret_cast<const char*>(&declared), 4);
    for (const auto& f : faces) {
        const float normal[3] = {0, 0, 0};
        bytes.append(reinterpret_cast<const char*>(normal), 12);
        for (const int i : f)
            bytes.append(reinterpret_cast<const char*>(v[std::size_t(i)].data()), 12);
        bytes.append(2, '\0');
    }
    return bytes + tail;
}

const char* const kTetraPlyHeader = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                    "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                    "end_header\n";
const char* const kTetraPlyBody = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

/// The tetrahedron as binary little-endian PLY, followed by `tail`.
std::string binaryPly(const std::string& tail)
{
    std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                        "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
    const float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    bytes.append(reinterpret_cast<const char*>(v), sizeof(v));
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& f : faces) {
        bytes.push_back(char(3));
        bytes.append(reinterpret_cast<const char*>(f), 12);
    }
    return bytes + tail;
}

/// A one-triangle glTF with an embedded buffer; `patch` edits its JSON text.
std::string gltf(const std::string& scene, const std::string& nodes, const std::string& bufferViewOffset,
                 const std::string& accessorView)
{
    // 36 bytes of positions, base64: the triangle (0,0,0), (1,0,0), (0,1,0).
    const std::string data = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    return R"({"asset":{"version":"2.0"},"scene":)" + scene + R"(,"scenes":[{"nodes":)" + nodes +
           R"(}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("accessors":[{"bufferView":)" +
           accessorView +
           R"(,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
           R"("bufferViews":[{"buffer":0,"byteOffset":)" +
           bufferViewOffset +
           R"(,"byteLength":36}],"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" + data +
           R"("}]})";
}

std::string loadError(const std::string& path)
{
    try {
        (void)loadMesh(path);
    } catch (const MeshLoadError& e) {
        return e.what();
    }
    return {};
}

} // namespace

class TestDeclaredSizes : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void wholeFilesLoad_data();
    void wholeFilesLoad();
    void disagreementsAreRefused_data();
    void disagreementsAreRefused();
    void unusableSurfacesAreRefused_data();
    void unusableSurfacesAreRefused();

private:
    QTemporaryDir m_dir;
};

void TestDeclaredSizes::initTestCase()
{
    QVERIFY(m_dir.isValid());
}

// The same files without the disagreement load: the refusals below are about it alone.
void TestDeclaredSizes::wholeFilesLoad_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::newRow("binary STL") << "whole.stl" << QByteArray::fromStdString(binaryStl(4));
    QTest::newRow("binary STL and a line break") << "newline.stl" << QByteArray::fromStdString(binaryStl(4, "\n"));
    QTest::newRow("ASCII PLY") << "whole.ply" << QByteArray(kTetraPlyHeader) + kTetraPlyBody;
    QTest::newRow("ASCII PLY and blank lines") << "blank.ply" << QByteArray(kTetraPlyHeader) + kTetraPlyBody + "\n\n";
    QTest::newRow("binary PLY") << "whole-binary.ply" << QByteArray::fromStdString(binaryPly(""));
    QTest::newRow("glTF") << "whole.gltf" << QByteArray::fromStdString(gltf("0", "[0]", "0", "0"));
}

void TestDeclaredSizes::wholeFilesLoad()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    const std::string path = m_dir.filePath(name).toStdString();
    writeFile(path, bytes.toStdString());
    const std::string error = loadError(path);
    QVERIFY2(error.empty(), error.c_str());
}

void TestDeclaredSizes::disagreementsAreRefused_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("message");
    QTest::newRow("STL count smaller than the data")
        << "short-count.stl" << QByteArray::fromStdString(binaryStl(3))
        << "the binary STL header declares 3 triangles (234 bytes), but the file has 284 bytes: 50 bytes follow";
    QTest::newRow("STL trailing bytes") << "tail.stl" << QByteArray::fromStdString(binaryStl(4, "extra"))
                                        << "5 bytes follow the last triangle";
    QTest::newRow("PLY property declared twice")
        << "twice.ply"
        << QByteArray("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float x\n"
                      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n") +
               kTetraPlyBody
        << "property 'x' of element 'vertex' is declared twice";
    QTest::newRow("ASCII PLY data after the last element")
        << "more.ply" << QByteArray(kTetraPlyHeader) + kTetraPlyBody + "3 0 1 2\n"
        << "the token '3' on line 18 follow the last element";
    QTest::newRow("binary PLY data after the last element")
        << "more-binary.ply" << QByteArray::fromStdString(binaryPly("0123456789"))
        << "10 bytes follow the last element";
    QTest::newRow("glTF scene index negative")
        << "scene-negative.gltf" << QByteArray::fromStdString(gltf("-2", "[0]", "0", "0"))
        << "\"scene\": -2 is negative";
    QTest::newRow("glTF scene index out of range")
        << "scene-range.gltf" << QByteArray::fromStdString(gltf("5", "[0]", "0", "0")) << "scene 5 does not exist";
    QTest::newRow("glTF node index negative")
        << "node-negative.gltf" << QByteArray::fromStdString(gltf("0", "[-3]", "0", "0")) << "node -3 does not exist";
    QTest::newRow("glTF buffer view offset negative")
        << "offset-negative.gltf" << QByteArray::fromStdString(gltf("0", "[0]", "-4", "0"))
        << "\"byteOffset\": -4 is negative";
    QTest::newRow("glTF buffer view offset past the buffer")
        << "offset-range.gltf" << QByteArray::fromStdString(gltf("0", "[0]", "4000000000", "0")) << "4000000000";
    QTest::newRow("glTF accessor view negative")
        << "view-negative.gltf" << QByteArray::fromStdString(gltf("0", "[0]", "0", "-1"))
        << "\"bufferView\": -1 is negative";
    QTest::newRow("OBJ whose vertices lie on a line")
        << "line.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 3 4\n")
        << "the geometry is degenerate: all 2 triangles have zero area";
    // Extreme integers: read without overflow (the OBJ one was undefined behaviour, -INT64_MIN,
    // and named vertex 4), each message naming the value read.
    QTest::newRow("OBJ index INT64_MIN")
        << "min.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -9223372036854775808 1 2\n")
        << "face references vertex -9223372036854775808 (counting back), but only 3 vertices are defined";
    QTest::newRow("OBJ index past int64")
        << "huge.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n")
        << "'99999999999999999999' is not a valid face corner";
    QTest::newRow("OFF count INT64_MIN") << "min.off"
                                         << QByteArray("OFF\n3 -9223372036854775808 0\n0 0 0\n1 0 0\n0 1 0\n")
                                         << "invalid face count '-9223372036854775808'";
    QTest::newRow("PLY count past uint64")
        << "huge-count.ply"
        << QByteArray("ply\nformat ascii 1.0\nelement vertex 18446744073709551616\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n") +
               kTetraPlyBody
        << "18446744073709551616";
    QTest::newRow("glTF accessor view out of range")
        << "view-range.gltf" << QByteArray::fromStdString(gltf("0", "[0]", "0", "9")) << "9";
}

void TestDeclaredSizes::disagreementsAreRefused()
{
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, message);
    const std::string path = m_dir.filePath(name).toStdString();
    writeFile(path, bytes.toStdString());
    const std::string error = loadError(path);
    QVERIFY2(!error.empty(), qPrintable(name + " loaded"));
    QVERIFY2(error.rfind(path, 0) == 0, error.c_str());
    QVERIFY2(QString::fromStdString(error).contains(message), error.c_str());
}

void TestDeclaredSizes::unusableSurfacesAreRefused_data()
{
    QTest::addColumn<QString>("points");
    QTest::addColumn<QString>("message");
    QTest::newRow("every control point the same") << "[[1,1,1],[1,1,1],[1,1,1],[1,1,1]]"
                                                  << "tessellation is unusable: the geometry is degenerate: all 2160";
    QTest::newRow("the net on a line") << "[[0,0,0],[1,0,0],[0,0,0],[1,0,0]]"
                                       << "tessellation is unusable: the geometry is degenerate: all 2256";
}

// NURBS files that parse but tessellate to nothing drawable rendered an empty picture with
// exit code 0; they are refused at load, naming the file and the surface.
void TestDeclaredSizes::unusableSurfacesAreRefused()
{
    QFETCH(QString, points);
    QFETCH(QString, message);
    const std::string path =
        m_dir.filePath(QString(QTest::currentDataTag()).replace(' ', '-') + ".nurbs.json").toStdString();
    writeFile(path, R"({"format":"trimlab-nurbs","version":1,"surfaces":[{"degreeU":1,"degreeV":1,"countU":2,)"
                    R"("countV":2,"knotsU":[0,0,1,1],"knotsV":[0,0,1,1],"points":)" +
                        points.toStdString() + R"(,"weights":[1,1,1,1]}]})");
    std::string error;
    try {
        (void)loadScene(path);
    } catch (const MeshLoadError& e) {
        error = e.what();
    }
    QVERIFY2(!error.empty(), "the surface loaded");
    QVERIFY2(error.rfind(path, 0) == 0 && error.find("surfaces[0]") != std::string::npos, error.c_str());
    QVERIFY2(QString::fromStdString(error).contains(message), error.c_str());
}

QTEST_GUILESS_MAIN(TestDeclaredSizes)
#include "tst_declared_sizes.moc"
