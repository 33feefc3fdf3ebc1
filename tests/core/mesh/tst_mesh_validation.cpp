// Mesh validation: each defect kind on a small hand-built mesh, the trimmable rule
// (closed, oriented 2-cycle) including non-manifold but balanced meshes, the report text,
// and the topology of real meshes.
#include "core/mesh/mesh_io.h"
#include "core/mesh/mesh_validation.h"

#include "test_paths.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace trimlab;
using trimlab::test::sharedDataPath;
using trimlab::test::testDataPath;

namespace {

// The unit cube [0,1]^3: 8 vertices, 12 outward triangles.
TriangleMesh unitCube()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    mesh.triangles = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                      {2, 3, 7}, {2, 7, 6}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
    return mesh;
}

TriangleMesh tetrahedron(const glm::vec3& offset = glm::vec3(0.0f))
{
    TriangleMesh mesh;
    mesh.positions = {offset, offset + glm::vec3(1, 0, 0), offset + glm::vec3(0, 1, 0), offset + glm::vec3(0, 0, 1)};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

// A torus as an n × m grid of quads (two triangles each), outward.
TriangleMesh torus(int n, int m)
{
    TriangleMesh mesh;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < m; ++j) {
            const double u = 2.0 * M_PI * i / n;
            const double v = 2.0 * M_PI * j / m;
            const double r = 2.0 + 0.5 * std::cos(v);
            mesh.positions.emplace_back(r * std::cos(u), r * std::sin(u), 0.5 * std::sin(v));
        }
    }
    auto index = [&](int i, int j) { return unsigned(((i + n) % n) * m + (j + m) % m); };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < m; ++j) {
            mesh.triangles.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1));
            mesh.triangles.emplace_back(index(i, j), index(i + 1, j + 1), index(i, j + 1));
        }
    }
    return mesh;
}

bool hasEdge(const DefectSamples<MeshEdge>& edges, unsigned a, unsigned b)
{
    for (const MeshEdge& e : edges.first) {
        if (e.a == a && e.b == b)
            return true;
    }
    return false;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

class TestMeshValidation : public QObject {
    Q_OBJECT
private slots:
    void closedCube();
    void tetrahedronVolume();
    void openSquareHasBoundary();
    void flippedFaceIsInconsistent();
    void cubesSharingAnEdgeAreTrimmable();
    void tetrahedraSharingAVertexAreTrimmable();
    void duplicatedTriangleIsUnbalanced();
    void doubleSidedSheetIsBalanced();
    void outOfRangeIndices();
    void nonFiniteVertices();
    void degenerateFaces();
    void unreferencedVertices();
    void samplesAreCapped();
    void emptyMesh();
    void torusHasGenusOne();
    void invertedCubeHasNegativeVolume();
    void reportText();
    void realData_data();
    void realData();
};

void TestMeshValidation::closedCube()
{
    const MeshValidationReport r = validateMesh(unitCube());
    QCOMPARE(r.vertexCount, std::size_t(8));
    QCOMPARE(r.triangleCount, std::size_t(12));
    QCOMPARE(r.edgeCount, std::size_t(18));
    QCOMPARE(r.componentCount, std::size_t(1));
    QVERIFY(r.closed());
    QVERIFY(r.manifold());
    QVERIFY(r.trimmable());
    QCOMPARE(r.trimUnavailableReason(), std::string());
    QCOMPARE(r.eulerCharacteristic, std::optional<std::int64_t>(2));
    QCOMPARE(r.genus, std::optional<std::int64_t>(0));
    QCOMPARE(r.signedVolume, 1.0);
    QCOMPARE(r.bounds.min, glm::dvec3(0.0));
    QCOMPARE(r.bounds.max, glm::dvec3(1.0));
    QVERIFY(!r.boundaryEdges.any() && !r.nonManifoldEdges.any() && !r.inconsistentEdges.any() &&
            !r.unbalancedEdges.any() && !r.nonManifoldVertices.any() && !r.degenerateFaces.any() &&
            !r.unreferencedVertices.any() && !r.nonFiniteVertices.any() && !r.outOfRangeFaces.any());
}

void TestMeshValidation::tetrahedronVolume()
{
    const MeshValidationReport r = validateMesh(tetrahedron());
    QVERIFY(std::abs(r.signedVolume - 1.0 / 6.0) < 1e-12);
    QCOMPARE(r.genus, std::optional<std::int64_t>(0));
}

void TestMeshValidation::openSquareHasBoundary()
{
    const MeshValidationReport r = validateMesh(loadMesh(testDataPath("meshes/open_square.obj")));
    QCOMPARE(r.boundaryEdges.count, std::size_t(4));
    QCOMPARE(r.unbalancedEdges.count, std::size_t(4));
    QVERIFY(hasEdge(r.boundaryEdges, 0, 1));
    QCOMPARE(r.boundaryEdges.first.front().forward, 1u);
    QVERIFY(!r.closed());
    QVERIFY(r.manifold());
    QVERIFY(!r.trimmable());
    QVERIFY(!r.eulerCharacteristic && !r.genus);
    QCOMPARE(
        r.trimUnavailableReason(),
        std::string("Trimming needs a closed surface: 4 boundary edges (first between vertices 0 and 1). "
                    "Close the holes (Edit ▸ Close Holes, --close-holes, or a mesh editor) to use the trim modes."));
}

void TestMeshValidation::flippedFaceIsInconsistent()
{
    const MeshValidationReport r = validateMesh(loadMesh(testDataPath("meshes/inconsistent_orientation.obj")));
    QVERIFY(r.closed());
    QVERIFY(r.manifold());
    QCOMPARE(r.inconsistentEdges.count, std::size_t(4));
    QVERIFY(hasEdge(r.inconsistentEdges, 4, 5));
    QVERIFY(!r.trimmable());
    QVERIFY(r.eulerCharacteristic.has_value());
    QVERIFY(!r.genus);
    const std::string reason = r.trimUnavailableReason();
    QVERIFY2(contains(reason, "Trimming needs consistently oriented faces: 4 edges are used twice in the same "
                              "direction (first between vertices 4 and 5)"),
             reason.c_str());
}

void TestMeshValidation::cubesSharingAnEdgeAreTrimmable()
{
    const MeshValidationReport r = validateMesh(loadMesh(testDataPath("meshes/nonmanifold_pair.obj")));
    QCOMPARE(r.nonManifoldEdges.count, std::size_t(1));
    QVERIFY(hasEdge(r.nonManifoldEdges, 2, 6));
    QCOMPARE(r.nonManifoldEdges.first.front().forward, 2u);
    QCOMPARE(r.nonManifoldEdges.first.front().backward, 2u);
    QCOMPARE(r.nonManifoldVertices.count, std::size_t(2));
    QCOMPARE(r.nonManifoldVertices.first, (std::vector<std::uint32_t>{2, 6}));
    QVERIFY(r.closed());
    QVERIFY(!r.manifold());
    QVERIFY(r.trimmable());
    QVERIFY(!r.eulerCharacteristic);
    QCOMPARE(r.componentCount, std::size_t(1));
    QCOMPARE(r.signedVolume, 2.0);
}

void TestMeshValidation::tetrahedraSharingAVertexAreTrimmable()
{
    // Two tetrahedra touching at the origin: the second is the first reflected through the
    // origin, with its winding reversed so it stays outward.
    TriangleMesh mesh = tetrahedron();
    mesh.positions.insert(mesh.positions.end(), {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}});
    mesh.triangles.insert(mesh.triangles.end(), {{0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}});
    const MeshValidationReport r = validateMesh(mesh);
    QVERIFY(r.closed());
    QCOMPARE(r.nonManifoldEdges.count, std::size_t(0));
    QCOMPARE(r.nonManifoldVertices.first, (std::vector<std::uint32_t>{0}));
    QVERIFY(!r.manifold());
    QVERIFY(r.trimmable());
    QCOMPARE(r.componentCount, std::size_t(1));
    QVERIFY(std::abs(r.signedVolume - 1.0 / 3.0) < 1e-12);
}

void TestMeshValidation::duplicatedTriangleIsUnbalanced()
{
    TriangleMesh mesh = unitCube();
    mesh.triangles.push_back(mesh.triangles[0]);
    const MeshValidationReport r = validateMesh(mesh);
    QVERIFY(r.closed());
    QCOMPARE(r.nonManifoldEdges.count, std::size_t(3));
    QCOMPARE(r.unbalancedEdges.count, std::size_t(3));
    QVERIFY(!r.trimmable());
    const std::string reason = r.trimUnavailableReason();
    QVERIFY2(contains(reason, "Trimming needs every edge to be used equally often in both directions: 3 edges are "
                              "not (first between vertices 0 and 2, used once from 0 to 2 and twice back)"),
             reason.c_str());
}

void TestMeshValidation::doubleSidedSheetIsBalanced()
{
    // A triangle and its reverse bound no volume; the winding number is 0 everywhere.
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
    const MeshValidationReport r = validateMesh(mesh);
    QVERIFY(r.trimmable());
    QVERIFY(r.closed());
    QCOMPARE(r.signedVolume, 0.0);
}

void TestMeshValidation::outOfRangeIndices()
{
    TriangleMesh mesh = unitCube();
    mesh.triangles[5] = {0, 5, 8};
    const MeshValidationReport r = validateMesh(mesh);
    QCOMPARE(r.outOfRangeFaces.count, std::size_t(1));
    QCOMPARE(r.outOfRangeFaces.first.front(), std::size_t(5));
    QCOMPARE(r.boundaryEdges.count, std::size_t(3)); // the face is left out of the edge analysis
    QVERIFY(!r.closed());
    QVERIFY(!r.trimmable());
    QVERIFY2(contains(r.trimUnavailableReason(), "1 face references vertices that do not exist (face 5)"),
             r.trimUnavailableReason().c_str());
}

void TestMeshValidation::nonFiniteVertices()
{
    TriangleMesh mesh = unitCube();
    mesh.positions[6].y = std::numeric_limits<float>::quiet_NaN();
    mesh.positions[7].x = std::numeric_limits<float>::infinity();
    const MeshValidationReport r = validateMesh(mesh);
    QCOMPARE(r.nonFiniteVertices.first, (std::vector<std::uint32_t>{6, 7}));
    QVERIFY(r.closed());
    QVERIFY(!r.trimmable());
    QVERIFY2(contains(r.trimUnavailableReason(), "2 vertices have NaN or infinite coordinates (first: vertex 6)"),
             r.trimUnavailableReason().c_str());
    QCOMPARE(r.bounds.max, glm::dvec3(1.0)); // bounds skip the bad vertices
}

void TestMeshValidation::degenerateFaces()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 3}, {0, 0, 3}, {0, 1, 2}};
    const MeshValidationReport r = validateMesh(mesh);
    QCOMPARE(r.degenerateFaces.first, (std::vector<std::size_t>{1, 2}));
    // The repeated-index face adds 0–3 in both directions; its collapsed side adds nothing.
    QVERIFY(!hasEdge(r.boundaryEdges, 0, 0));
}

void TestMeshValidation::unreferencedVertices()
{
    TriangleMesh mesh = unitCube();
    mesh.positions.emplace_back(5, 5, 5);
    mesh.positions.emplace_back(6, 6, 6);
    const MeshValidationReport r = validateMesh(mesh);
    QCOMPARE(r.unreferencedVertices.first, (std::vector<std::uint32_t>{8, 9}));
    QVERIFY(r.trimmable());
    QCOMPARE(r.eulerCharacteristic, std::optional<std::int64_t>(2)); // counts referenced vertices only
    QCOMPARE(r.componentCount, std::size_t(1));
}

void TestMeshValidation::samplesAreCapped()
{
    const MeshValidationReport r = validateMesh(torus(8, 6));
    QVERIFY(r.trimmable());
    TriangleMesh open = torus(8, 6);
    open.triangles.resize(open.triangles.size() - 12); // remove a ring of faces
    const MeshValidationReport o = validateMesh(open);
    QCOMPARE(o.boundaryEdges.count, std::size_t(12));
    QCOMPARE(o.boundaryEdges.first.size(), DefectSamples<MeshEdge>::kMaxSamples);
}

void TestMeshValidation::emptyMesh()
{
    const MeshValidationReport r = validateMesh(TriangleMesh{});
    QVERIFY(!r.trimmable());
    QVERIFY(!r.closed());
    QCOMPARE(r.componentCount, std::size_t(0));
    QCOMPARE(r.trimUnavailableReason(), std::string("Trimming needs a closed surface, but the mesh has no triangles."));
}

void TestMeshValidation::torusHasGenusOne()
{
    const MeshValidationReport r = validateMesh(torus(8, 6));
    QCOMPARE(r.eulerCharacteristic, std::optional<std::int64_t>(0));
    QCOMPARE(r.genus, std::optional<std::int64_t>(1));
    QVERIFY(r.signedVolume > 0.0);
    // Two disjoint pieces: genus adds up.
    TriangleMesh two = torus(8, 6);
    appendMesh(two, tetrahedron(glm::vec3(10, 0, 0)));
    const MeshValidationReport t = validateMesh(two);
    QCOMPARE(t.componentCount, std::size_t(2));
    QCOMPARE(t.eulerCharacteristic, std::optional<std::int64_t>(2));
    QCOMPARE(t.genus, std::optional<std::int64_t>(1));
}

void TestMeshValidation::invertedCubeHasNegativeVolume()
{
    TriangleMesh mesh = unitCube();
    for (glm::uvec3& t : mesh.triangles)
        std::swap(t[1], t[2]);
    const MeshValidationReport r = validateMesh(mesh);
    QCOMPARE(r.signedVolume, -1.0);
    QVERIFY(r.trimmable()); // consistently oriented, just inside out
}

void TestMeshValidation::reportText()
{
    const std::string good = formatReport(validateMesh(unitCube()), "cube.obj");
    QVERIFY2(good.rfind("cube.obj\n", 0) == 0, good.c_str());
    for (const char* line :
         {"  vertices:               8\n", "  triangles:              12\n", "  components:             1\n",
          "  Euler characteristic:   2\n", "  genus:                  0\n", "  signed volume:          1\n",
          "  boundary edges:         0\n", "  bounding box:           min (0, 0, 0), max (1, 1, 1), size 1 x 1 x 1\n"})
        QVERIFY2(contains(good, line), qPrintable(QString::fromStdString(good) + "lacks: " + line));
    QVERIFY2(good.size() > 20 && good.substr(good.size() - 22) == "trim modes: available\n", good.c_str());

    const std::string open = formatReport(validateMesh(loadMesh(testDataPath("meshes/open_square.obj"))), "open");
    QVERIFY2(contains(open, "  boundary edges:         4 (first: 0-1, 0-3, 1-2, 2-3)\n"), open.c_str());
    QVERIFY2(contains(open, "  genus:                  n/a (not a closed manifold)\n"), open.c_str());
    QVERIFY2(contains(open, "trim modes: unavailable \xE2\x80\x94 Trimming needs a closed surface: 4 boundary edges"),
             open.c_str());
}

void TestMeshValidation::realData_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("closed");
    QTest::addColumn<bool>("trimmable");
    QTest::addColumn<int>("boundaryEdges");
    QTest::addColumn<int>("genus"); // −1: not checked
    QTest::newRow("cgal-man") << "selfintersect/cgal-man.off.gz" << true << true << 0 << -1;
    QTest::newRow("walking-cat") << "anim/walking-cat/mesh.01.obj.gz" << false << false << 20 << -1;
    QTest::newRow("dem-bones") << "anim/dem-bones/frames/frame_000.obj.gz" << true << true << 0 << -1;
    QTest::newRow("torus") << "static/odedstein-torus.obj.gz" << true << true << 0 << 1;
    QTest::newRow("cgal-pig") << "selfintersect/cgal-pig.off.gz" << false << false << 55 << -1;
}

void TestMeshValidation::realData()
{
    QFETCH(QString, file);
    QFETCH(bool, closed);
    QFETCH(bool, trimmable);
    QFETCH(int, boundaryEdges);
    QFETCH(int, genus);
    const std::filesystem::path path = sharedDataPath(file.toStdString());
    if (!std::filesystem::exists(path))
        QSKIP(qPrintable("shared data missing: " + QString::fromStdString(path.string())));
    const MeshValidationReport r = validateMesh(loadMesh(path));
    QCOMPARE(r.closed(), closed);
    QCOMPARE(r.trimmable(), trimmable);
    QCOMPARE(int(r.boundaryEdges.count), boundaryEdges);
    if (genus >= 0)
        QCOMPARE(r.genus, std::optional<std::int64_t>(genus));
    if (!trimmable)
        QVERIFY2(contains(r.trimUnavailableReason(), std::to_string(boundaryEdges) + " boundary edges"),
                 r.trimUnavailableReason().c_str());
}

QTEST_APPLESS_MAIN(TestMeshValidation)
#include "tst_mesh_validation.moc"
