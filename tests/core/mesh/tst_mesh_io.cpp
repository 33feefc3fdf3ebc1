// Mesh loading: every good test file in every format loads with the exact expected counts
// and coordinates; every broken file is rejected with a MeshLoadError that says why; gzip
// variants and in-memory loading agree with plain files; real third-party meshes load.
#include "core/mesh/gzip_input.h"
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_validation.h"

#include "test_paths.h"

#include <glm/geometric.hpp>

#include <QElapsedTimer>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>

using namespace trimlab;
using trimlab::test::sharedDataPath;
using trimlab::test::testDataPath;

namespace {

TriangleMesh loadTestMesh(const std::string& relative)
{
    return loadMesh(testDataPath(relative));
}

std::string readBytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The message of the MeshLoadError `load` throws, or "" if it throws none.
std::string loadError(const std::function<void()>& load)
{
    try {
        load();
    } catch (const MeshLoadError& e) {
        return e.what();
    }
    return {};
}

bool identical(const TriangleMesh& a, const TriangleMesh& b)
{
    return a.positions == b.positions && a.triangles == b.triangles;
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f)
{
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

QString text(const glm::vec3& v)
{
    return QString("(%1, %2, %3)").arg(double(v.x)).arg(double(v.y)).arg(double(v.z));
}

} // namespace

class TestMeshIo : public QObject {
    Q_OBJECT
private slots:
    void goodFiles_data();
    void goodFiles();
    void cubeFormatsAgree_data();
    void cubeFormatsAgree();
    void gzipVariantsMatch_data();
    void gzipVariantsMatch();
    void brokenFiles_data();
    void brokenFiles();
    void errorsCarryTheirLocation();
    void hugeDeclaredCountsFailFast();
    void gzipOutputIsCapped();
    void fileSystemErrors();
    void loadFromMemory();
    void plyPolygonsAreTriangulated();
    void asciiStlWithSeveralSolids();
    void stlKeepsDegenerateFacets();
    void stlIsWeldedIntoAClosedMesh();
    void nonConvexFacesKeepTheirOrientation();
    void gltfNodeTransformsAreApplied();
    void gltfMirroredNodeStaysOutward();
    void gltfStripsAndFansFaceTheSameWay();
    void gltfSplitVerticesAreWelded();
    void supportedExtensionsListsEveryFormat();
    void realData_data();
    void realData();
};

void TestMeshIo::goodFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<int>("spotVertex");
    QTest::addColumn<float>("x");
    QTest::addColumn<float>("y");
    QTest::addColumn<float>("z");
    // Counts and coordinates written out from the files (see tests/data/README.md).
    struct Row {
        const char* file;
        int v, t, spot;
        float x, y, z;
    };
    const Row rows[] = {
        {"meshes/cube.obj", 8, 12, 6, 1, 1, 1},
        {"meshes/cube_features.obj", 8, 12, 1, 1, 0, 0},
        {"meshes/tetrahedron.obj", 4, 4, 3, 0, 0, 1},
        {"meshes/open_square.obj", 4, 2, 2, 1, 1, 0},
        {"meshes/nonmanifold_pair.obj", 14, 24, 9, 2, 2, 0},
        {"meshes/inconsistent_orientation.obj", 8, 12, 7, 0, 1, 1},
        {"meshes/nonconvex.obj", 10, 6, 9, 10.5f, 1, 0},
        {"meshes/cube.off", 8, 12, 4, 0, 0, 1},
        {"meshes/cube_colored.off", 8, 12, 5, 1, 0, 1},
        {"meshes/tetrahedron.off", 4, 4, 2, 0, 1, 0},
        {"meshes/cube_ascii.ply", 8, 12, 2, 1, 1, 0},
        {"meshes/cube_binary_le.ply", 8, 12, 6, 1, 1, 1},
        {"meshes/cube_binary_be.ply", 8, 12, 7, 0, 1, 1},
        // STL vertices are numbered by first appearance after welding: (0,0,0), (0,1,0), ...
        {"meshes/cube_ascii.stl", 8, 12, 1, 0, 1, 0},
        {"meshes/cube_binary.stl", 8, 12, 3, 1, 0, 0},
        {"meshes/cube_binary_solid_header.stl", 8, 12, 3, 1, 0, 0},
        // Node 0: cube scaled 2, turned 90° about z, moved to x = 5: (1,1,1) -> (3,2,2).
        {"meshes/two_nodes.gltf", 16, 24, 6, 3, 2, 2},
        // Node 1 (under node 2): mirrored in x, moved to x = -5: (1,1,1) -> (-6,1,1).
        {"meshes/two_nodes.glb", 16, 24, 14, -6, 1, 1},
        // The last vertex comes from a sparse accessor: (9,9,9) replaced by (4,1,0).
        {"meshes/strip_fan.gltf", 12, 6, 11, 4, 1, 0},
        {"meshes/tetrahedron.glb", 4, 4, 3, 0, 0, 1},
    };
    for (const Row& r : rows)
        QTest::newRow(r.file) << r.file << r.v << r.t << r.spot << r.x << r.y << r.z;
}

void TestMeshIo::goodFiles()
{
    QFETCH(QString, file);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    QFETCH(int, spotVertex);
    QFETCH(float, x);
    QFETCH(float, y);
    QFETCH(float, z);
    const TriangleMesh mesh = loadTestMesh(file.toStdString());
    QCOMPARE(int(mesh.vertexCount()), vertices);
    QCOMPARE(int(mesh.triangleCount()), triangles);
    const glm::vec3 spot = mesh.positions.at(std::size_t(spotVertex));
    QVERIFY2(near(spot, {x, y, z}), qPrintable("vertex " + QString::number(spotVertex) + " is " + text(spot)));
    const MeshValidationReport report = validateMesh(mesh);
    QVERIFY(!report.outOfRangeFaces.any());
    QVERIFY(!report.nonFiniteVertices.any());
}

void TestMeshIo::cubeFormatsAgree_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("reference");
    QTest::newRow("obj features") << "meshes/cube_features.obj"
                                  << "meshes/cube.obj";
    QTest::newRow("off") << "meshes/cube.off"
                         << "meshes/cube.obj";
    QTest::newRow("coff") << "meshes/cube_colored.off"
                          << "meshes/cube.obj";
    QTest::newRow("ply le") << "meshes/cube_binary_le.ply"
                            << "meshes/cube_ascii.ply";
    QTest::newRow("ply be") << "meshes/cube_binary_be.ply"
                            << "meshes/cube_ascii.ply";
    // The quads of cube.obj split along their first diagonal are cube_ascii.ply's triangles.
    QTest::newRow("obj vs ply") << "meshes/cube.obj"
                                << "meshes/cube_ascii.ply";
    QTest::newRow("stl binary") << "meshes/cube_binary.stl"
                                << "meshes/cube_ascii.stl";
    QTest::newRow("stl solid header") << "meshes/cube_binary_solid_header.stl"
                                      << "meshes/cube_ascii.stl";
    QTest::newRow("glb") << "meshes/two_nodes.glb"
                         << "meshes/two_nodes.gltf";
}

void TestMeshIo::cubeFormatsAgree()
{
    QFETCH(QString, file);
    QFETCH(QString, reference);
    QVERIFY(identical(loadTestMesh(file.toStdString()), loadTestMesh(reference.toStdString())));
}

void TestMeshIo::gzipVariantsMatch_data()
{
    QTest::addColumn<QString>("compressed");
    QTest::addColumn<QString>("plain");
    for (const char* name : {"cube.obj", "cube.off", "cube_ascii.ply", "cube_binary_le.ply", "cube_ascii.stl",
                             "cube_binary.stl", "two_nodes.glb", "two_nodes.gltf", "strip_fan.gltf"})
        QTest::newRow(name) << QString("meshes/%1.gz").arg(name) << QString("meshes/%1").arg(name);
    QTest::newRow("magic without .gz") << "meshes/cube_gzip_magic.obj"
                                       << "meshes/cube.obj";
    QTest::newRow("two gzip members") << "meshes/cube_multimember.obj.gz"
                                      << "meshes/cube.obj";
}

void TestMeshIo::gzipVariantsMatch()
{
    QFETCH(QString, compressed);
    QFETCH(QString, plain);
    QVERIFY(identical(loadTestMesh(compressed.toStdString()), loadTestMesh(plain.toStdString())));
}

void TestMeshIo::brokenFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("phrase");
    struct Row {
        const char* file;
        const char* phrase;
    };
    const Row rows[] = {
        // OBJ (no header, so no "wrong magic"; no declared counts, so no "huge count")
        {"empty.obj", "the file is empty (0 bytes)"},
        {"garbage.obj", "binary data in a text format"},
        {"truncated.obj", "a vertex needs 3 coordinates"},
        {"nan.obj", "vertex 2 has a non-finite coordinate (nan)"},
        {"inf.obj", "vertex 3 has a non-finite coordinate (inf)"},
        {"not_a_number.obj", "'abc' is not a number"},
        {"out_of_range.obj", "face 6 references vertex 9, but the file has only 8 vertices"},
        {"zero_index.obj", "vertex index 0 is invalid"},
        {"negative_out_of_range.obj", "only 3 vertices are defined before this line"},
        {"face_two_vertices.obj", "the face has 2 vertices; a face needs at least 3"},
        {"bad_corner.obj", "'/2' is not a valid face corner"},
        {"no_faces.obj", "contains no faces"},
        // OFF
        {"empty.off", "the file is empty (0 bytes)"},
        {"garbage.off", "binary data in a text format"},
        {"wrong_header.off", "not an OFF file"},
        {"four_d.off", "is not supported; only 3D OFF is"},
        {"binary.off", "binary OFF is not supported"},
        {"bad_counts.off", "invalid vertex count 'three'"},
        {"truncated.off", "truncated: the header declares 8 vertices, but the file ends after 5"},
        {"truncated_faces.off", "truncated: the header declares 4 faces, but the file ends after 2"},
        {"huge_count.off", "declares 2000000000 vertices, but the file ends after 3"},
        {"nan.off", "vertex 2: the vertex has a non-finite coordinate (nan)"},
        {"out_of_range.off", "face 1: the face references vertex 4, but the file has only 4 vertices"},
        {"negative_index.off", "vertex index -1 is negative"},
        {"face_two_vertices.off", "the face has 2 vertices; a face needs at least 3"},
        {"face_short.off", "the face declares 4 vertices but lists only 3"},
        {"no_faces.off", "contains no faces"},
        // PLY
        {"empty.ply", "the file is empty (0 bytes)"},
        {"garbage.ply", "not a PLY file"},
        {"wrong_magic.ply", "not a PLY file"},
        {"bad_format.ply", "unknown PLY format 'binary_middle_endian'"},
        {"bad_type.ply", "unknown property type 'float128'"},
        {"missing_end_header.ply", "is the 'end_header' line missing?"},
        {"missing_xyz.ply", "no scalar property 'z'"},
        {"no_face_element.ply", "contains no faces"},
        {"truncated_ascii.ply", "truncated: the data ends at vertex 5, but the header declares 8"},
        {"truncated_binary.ply", "truncated: face 6 declares 3 entries"},
        {"huge_count.ply", "but the header declares 2000000000 'vertex' elements"},
        {"huge_count_binary.ply", "truncated: the data ends at vertex 4, but the header declares 2000000000"},
        {"huge_list.ply", "declares 4000000000 entries in list 'vertex_indices'"},
        {"nan_ascii.ply", "vertex 2: the vertex has a non-finite coordinate (nan)"},
        {"nan_binary.ply", "vertex 5 (byte offset 613): the vertex has a non-finite coordinate (nan)"},
        {"not_a_number.ply", "'zero' is not a valid number"},
        {"out_of_range.ply", "the face references vertex 9, but the file has only 3 vertices"},
        {"negative_index.ply", "vertex index -1 is negative"},
        {"negative_index_binary.ply", "vertex index -5 is negative"},
        {"face_two_vertices.ply", "the face has 2 vertices; a face needs at least 3"},
        // STL
        {"empty.stl", "the file is empty (0 bytes)"},
        {"garbage.stl", "truncated binary STL"},
        {"wrong_header.stl", "not an STL file"},
        {"truncated_ascii.stl", "truncated ASCII STL"},
        {"truncated_binary.stl", "declares 12 triangles, which need 684 bytes, but the file has only 354"},
        {"huge_count.stl", "declares 2000000000 triangles"},
        {"nan_ascii.stl", "facet 0: the facet has a non-finite coordinate (nan)"},
        {"nan_binary.stl", "triangle 2 (byte offset 184): the triangle has a non-finite coordinate (nan)"},
        {"facet_two_vertices.stl", "facet 0 has 2 vertices; a facet needs 3"},
        {"bad_keyword.stl", "expected 'vertex' or 'endloop', found 'vertx'"},
        {"no_facets.stl", "contains no faces"},
        {"zero_facets.stl", "contains no faces"},
        // glTF / GLB
        {"empty.gltf", "the file is empty (0 bytes)"},
        {"empty.glb", "the file is empty (0 bytes)"},
        {"garbage.gltf", "not a glTF file"},
        {"garbage.glb", "not a glTF file"},
        {"wrong_magic.glb", "not a glTF file"},
        {"version1.glb", "binary glTF version 1 is not supported"},
        {"truncated.glb", "truncated binary glTF: the header declares 976 bytes, but the file has only 100"},
        {"invalid_json.gltf", "invalid glTF"},
        {"missing_bin.gltf", "missing.bin"},
        {"points_only.gltf", "contains no triangles, only points or lines"},
        {"accessor_out_of_bounds.gltf", "mesh 0 primitive 0: accessor 0: 100 elements of 12 bytes"},
        {"huge_count.gltf", "accessor 0: 2000000000 elements of 12 bytes from byte offset 0 do not fit"},
        {"index_out_of_range.gltf", "accessor 1: index 8 (element 35) is out of range"},
        {"nan.gltf", "accessor 0: position 5 has a non-finite coordinate (nan)"},
        {"missing_position.gltf", "no POSITION attribute"},
        {"node_cycle.gltf", "node 0 is reached twice"},
        {"bad_node_reference.gltf", "node 7 does not exist"},
        {"draco_required.gltf", "'KHR_draco_mesh_compression', which TrimLab does not implement"},
        {"bad_triangle_count.gltf", "34 indices, which is not a multiple of 3"},
        // gzip
        {"truncated.obj.gz", "truncated gzip data"},
        {"corrupt.off.gz", "corrupt gzip data"},
        {"not_gzip.obj.gz", "is named .gz but is not gzip data"},
        {"empty.stl.gz", "the file is empty (0 bytes)"},
        {"empty_content.obj.gz", "empty after gzip decompression"},
        {"trailing_garbage.ply.gz", "unexpected 8 bytes after the end of the gzip data"},
    };
    for (const Row& r : rows)
        QTest::newRow(r.file) << r.file << r.phrase;
}

void TestMeshIo::brokenFiles()
{
    QFETCH(QString, file);
    QFETCH(QString, phrase);
    const std::filesystem::path path = testDataPath("broken/" + file.toStdString());
    QVERIFY2(std::filesystem::exists(path), qPrintable(file + " is missing"));
    const std::string message = loadError([&] { (void)loadMesh(path); });
    QVERIFY2(!message.empty(), qPrintable(file + " loaded without error"));
    QVERIFY2(message.find(phrase.toStdString()) != std::string::npos,
             qPrintable("message '" + QString::fromStdString(message) + "' lacks '" + phrase + "'"));
    QVERIFY2(message.rfind(path.string(), 0) == 0, "the message must start with the file name");
}

void TestMeshIo::errorsCarryTheirLocation()
{
    try {
        (void)loadTestMesh("broken/out_of_range.obj");
        QFAIL("no error");
    } catch (const MeshLoadError& e) {
        QCOMPARE(e.line(), std::optional<std::size_t>(15));
        QVERIFY(e.element().empty());
        QCOMPARE(e.file(), testDataPath("broken/out_of_range.obj").string());
        QCOMPARE(e.reason(), std::string("face 6 references vertex 9, but the file has only 8 vertices"));
        QCOMPARE(std::string(e.what()), e.file() + ":15: " + e.reason());
    }
    try {
        (void)loadTestMesh("broken/negative_index_binary.ply");
        QFAIL("no error");
    } catch (const MeshLoadError& e) {
        QVERIFY(!e.line());
        QCOMPARE(e.element(), std::string("face 0 (byte offset 207)"));
    }
    const MeshLoadError error("cube.obj", "face 5 references vertex 9, but the file has only 8 vertices",
                              {.line = 12, .element = {}});
    QCOMPARE(std::string(error.what()),
             std::string("cube.obj:12: face 5 references vertex 9, but the file has only 8 vertices"));
    const MeshLoadError elementError("mesh.ply", "bad", {.line = 0, .element = "face 3"});
    QCOMPARE(std::string(elementError.what()), std::string("mesh.ply: face 3: bad"));
}

// A header that lies about its size must fail at the end of the data, not after trying to
// allocate or loop over billions of items.
void TestMeshIo::hugeDeclaredCountsFailFast()
{
    for (const char* file : {"huge_count.off", "huge_count.ply", "huge_count_binary.ply", "huge_list.ply",
                             "huge_count.stl", "huge_count.gltf"}) {
        QElapsedTimer timer;
        timer.start();
        QVERIFY_THROWS_EXCEPTION(MeshLoadError, (void)loadTestMesh(std::string("broken/") + file));
        QVERIFY2(timer.elapsed() < 1000, file);
    }
}

void TestMeshIo::gzipOutputIsCapped()
{
    const std::string compressed = readBytes(testDataPath("meshes/cube.obj.gz"));
    const std::string plain = readBytes(testDataPath("meshes/cube.obj"));
    QCOMPARE(gunzip(compressed, "cube.obj.gz", plain.size()), plain);
    const std::string message = loadError([&] { (void)gunzip(compressed, "cube.obj.gz", 100); });
    QVERIFY2(message.find("decompresses to more than 100 bytes") != std::string::npos, message.c_str());
    QVERIFY(hasGzipMagic(compressed));
    QVERIFY(!hasGzipMagic(plain));
    QCOMPARE(kMaxMeshInputBytes, std::size_t(2) << 30);
}

void TestMeshIo::fileSystemErrors()
{
    std::string message = loadError([] { (void)loadTestMesh("meshes/does_not_exist.obj"); });
    QVERIFY2(message.find("does not exist") != std::string::npos, message.c_str());
    message = loadError([] { (void)loadTestMesh("meshes/two_nodes.bin"); });
    QVERIFY2(message.find("unsupported file extension '.bin'; supported: .obj, .off, .ply, .stl, .gltf, .glb") !=
                 std::string::npos,
             message.c_str());
    message = loadError([] { (void)loadMesh(testDataPath("README.md").parent_path() / "meshes"); });
    QVERIFY2(message.find("no mesh extension") != std::string::npos, message.c_str());
    // Extensions are case-insensitive.
    const std::filesystem::path upper = test::outputDir() / "CUBE.OBJ";
    std::filesystem::copy_file(testDataPath("meshes/cube.obj"), upper,
                               std::filesystem::copy_options::overwrite_existing);
    QCOMPARE(loadMesh(upper).triangleCount(), std::size_t(12));
    const std::filesystem::path folder = test::outputDir() / "folder.obj";
    std::filesystem::create_directories(folder);
    message = loadError([&] { (void)loadMesh(folder); });
    QVERIFY2(message.find("it is a folder") != std::string::npos, message.c_str());
}

void TestMeshIo::loadFromMemory()
{
    const TriangleMesh reference = loadTestMesh("meshes/cube.obj");
    const std::string plain = readBytes(testDataPath("meshes/cube.obj"));
    const std::string compressed = readBytes(testDataPath("meshes/cube.obj.gz"));
    for (const char* extension : {"obj", ".obj", "OBJ", "mesh.obj"})
        QVERIFY2(identical(loadMeshFromMemory(plain, extension, "memory"), reference), extension);
    for (const char* extension : {"obj", "obj.gz", ".OBJ.GZ"})
        QVERIFY2(identical(loadMeshFromMemory(compressed, extension, "memory"), reference), extension);
    const std::string glb = readBytes(testDataPath("meshes/two_nodes.glb"));
    QCOMPARE(loadMeshFromMemory(glb, "glb", "memory").triangleCount(), std::size_t(24));
    // An external buffer cannot be resolved without a folder.
    const std::string gltf = readBytes(testDataPath("meshes/two_nodes.gltf"));
    std::string message = loadError([&] { (void)loadMeshFromMemory(gltf, "gltf", "memory.gltf"); });
    QVERIFY2(message.rfind("memory.gltf: invalid glTF", 0) == 0, message.c_str());
    QVERIFY2(message.find("'two_nodes.bin' cannot be read when loading from memory") != std::string::npos,
             message.c_str());
    QVERIFY(identical(loadMeshFromMemory("\xEF\xBB\xBF" + plain, "obj", "bom.obj"), reference));
    message = loadError([&] { (void)loadMeshFromMemory(plain, "xyz", "memory"); });
    QVERIFY2(message.find("unsupported file extension '.xyz'") != std::string::npos, message.c_str());
    message = loadError([&] { (void)loadMeshFromMemory("", "stl", "memory"); });
    QVERIFY2(message.find("empty") != std::string::npos, message.c_str());
}

void TestMeshIo::plyPolygonsAreTriangulated()
{
    const std::string ply = "ply\r\nformat ascii 1.0\r\nelement vertex 5\r\nproperty uchar x\r\nproperty short y\r\n"
                            "property double z\r\nelement face 1\r\nproperty list int ushort vertex_index\r\n"
                            "end_header\r\n0 0 0\r\n2 0 0\r\n2 2 0\r\n1 1 0\r\n0 2 0\r\n5 0 1 2 3 4\r\n";
    const TriangleMesh mesh = loadMeshFromMemory(ply, "ply", "pentagon.ply");
    QCOMPARE(mesh.vertexCount(), std::size_t(5));
    QCOMPARE(mesh.triangleCount(), std::size_t(3));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 n =
            glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
        QVERIFY2(n.z > 0.0f, "every triangle of the non-convex pentagon faces +z");
    }
}

void TestMeshIo::asciiStlWithSeveralSolids()
{
    const std::string stl = "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                            "endloop\nendfacet\nendsolid a\nsolid b\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\n"
                            "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid b\n";
    const TriangleMesh mesh = loadMeshFromMemory(stl, "stl", "two.stl");
    QCOMPARE(mesh.triangleCount(), std::size_t(2));
    QCOMPARE(mesh.vertexCount(), std::size_t(4)); // the shared edge is welded
}

void TestMeshIo::stlKeepsDegenerateFacets()
{
    const std::string stl = "solid d\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                            "endloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 0\n"
                            "vertex -0 1 0\nendloop\nendfacet\nendsolid d\n";
    const TriangleMesh mesh = loadMeshFromMemory(stl, "stl", "degenerate.stl");
    QCOMPARE(mesh.triangleCount(), std::size_t(2));
    QCOMPARE(mesh.vertexCount(), std::size_t(3)); // −0 welds with +0
    QCOMPARE(mesh.triangles[1], glm::uvec3(0, 0, 2));
}

void TestMeshIo::stlIsWeldedIntoAClosedMesh()
{
    for (const char* file : {"meshes/cube_ascii.stl", "meshes/cube_binary.stl"}) {
        const MeshValidationReport report = validateMesh(loadTestMesh(file));
        QVERIFY2(report.closed() && report.trimmable(), file);
        QCOMPARE(report.signedVolume, 1.0);
    }
}

void TestMeshIo::nonConvexFacesKeepTheirOrientation()
{
    const TriangleMesh mesh = loadTestMesh("meshes/nonconvex.obj");
    double area = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const double z = glm::cross(b - a, c - a).z;
        QVERIFY2(z > 0.0, "a triangle of a non-convex face is flipped");
        area += 0.5 * z;
    }
    QCOMPARE(area, 3.0 + 1.5); // the L hexagon and the dart
}

void TestMeshIo::gltfNodeTransformsAreApplied()
{
    const TriangleMesh mesh = loadTestMesh("meshes/two_nodes.gltf");
    // Node 0 = T(5,0,0) R(90° about z) S(2): (1,0,0) -> (2,0,0) -> (0,2,0) -> (5,2,0).
    QVERIFY2(near(mesh.positions[1], {5, 2, 0}), qPrintable(text(mesh.positions[1])));
    // Node 1 under node 2 = T(-5,0,0) S(-1,1,1): (1,0,0) -> (-1,0,0) -> (-6,0,0).
    QVERIFY2(near(mesh.positions[9], {-6, 0, 0}), qPrintable(text(mesh.positions[9])));
    // The decoy in the non-default scene 0 (at x = 100) is not loaded.
    QVERIFY(computeBounds(mesh).max.x < 10.0);
}

void TestMeshIo::gltfMirroredNodeStaysOutward()
{
    const TriangleMesh mesh = loadTestMesh("meshes/two_nodes.glb");
    const MeshValidationReport report = validateMesh(mesh);
    QVERIFY(report.trimmable());
    QCOMPARE(report.componentCount, std::size_t(2));
    // 2³ for the scaled cube plus 1 for the mirrored one: both positive, so outward.
    QVERIFY2(std::abs(report.signedVolume - 9.0) < 1e-5, qPrintable(QString::number(report.signedVolume)));
    TriangleMesh mirroredOnly;
    mirroredOnly.positions.assign(mesh.positions.begin() + 8, mesh.positions.end());
    for (std::size_t i = 12; i < 24; ++i)
        mirroredOnly.triangles.push_back(mesh.triangles[i] - glm::uvec3(8));
    QVERIFY(validateMesh(mirroredOnly).signedVolume > 0.0);
}

// Exporters split vertices at normal/UV seams; the loader must join identical positions
// (also across primitives) or a closed model would never be trimmable.
void TestMeshIo::gltfSplitVerticesAreWelded()
{
    const TriangleMesh mesh = loadTestMesh("meshes/cube_split_vertices.gltf");
    QCOMPARE(mesh.vertexCount(), std::size_t(8));
    QCOMPARE(mesh.triangleCount(), std::size_t(12));
    const MeshValidationReport report = validateMesh(mesh);
    QVERIFY2(report.trimmable(), report.trimUnavailableReason().c_str());
    QVERIFY(report.signedVolume > 0.99 && report.signedVolume < 1.01);
}

void TestMeshIo::gltfStripsAndFansFaceTheSameWay()
{
    const TriangleMesh mesh = loadTestMesh("meshes/strip_fan.gltf");
    double area = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const double z = glm::cross(b - a, c - a).z;
        QVERIFY2(z > 0.0, "strip, fan and list triangles all face +z");
        area += 0.5 * z;
    }
    // The strip's unit square, the fan's three quarter-unit triangles (a fan does not close
    // back to its first rim vertex) and one half-unit triangle.
    QCOMPARE(area, 1.0 + 0.75 + 0.5);
}

void TestMeshIo::supportedExtensionsListsEveryFormat()
{
    const std::vector<std::string> expected = {"obj",    "off",    "ply",    "stl",    "gltf",    "glb",
                                               "obj.gz", "off.gz", "ply.gz", "stl.gz", "gltf.gz", "glb.gz"};
    QCOMPARE(supportedMeshExtensions(), expected);
}

void TestMeshIo::realData_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("triangles");
    QTest::newRow("cgal-man") << "selfintersect/cgal-man.off.gz" << 17495 << 34986;
    QTest::newRow("spot") << "static/odedstein-spot.obj.gz" << 11533 << 23062;
    // 1175 quads, 59 triangles, 37 pentagons, 14 hexagons: Σ(n−2) = 2350 + 59 + 111 + 56.
    QTest::newRow("walking-cat") << "anim/walking-cat/mesh.01.obj.gz" << 1297 << 2576;
    QTest::newRow("dem-bones") << "anim/dem-bones/frames/frame_000.obj.gz" << 754 << 1504;
    QTest::newRow("torus") << "static/odedstein-torus.obj.gz" << 2304 << 4608;
    QTest::newRow("cgal-pig") << "selfintersect/cgal-pig.off.gz" << 468 << 891;
}

void TestMeshIo::realData()
{
    QFETCH(QString, file);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    const std::filesystem::path path = sharedDataPath(file.toStdString());
    if (!std::filesystem::exists(path))
        QSKIP(qPrintable("shared data missing: " + QString::fromStdString(path.string())));
    const TriangleMesh mesh = loadMesh(path);
    QCOMPARE(int(mesh.vertexCount()), vertices);
    QCOMPARE(int(mesh.triangleCount()), triangles);
}

QTEST_APPLESS_MAIN(TestMeshIo)
#include "tst_mesh_io.moc"
