// TriangleMesh <-> OpenMesh: closed meshes round-trip exactly; faces a half-edge mesh
// cannot hold are counted, not printed.
#include "core/mesh/mesh_io.h"
#include "core/mesh/openmesh_adapter.h"

#include "test_paths.h"

#include <QtTest>

#include <iostream>
#include <sstream>

using namespace trimlab;
using trimlab::test::testDataPath;

namespace {

// Captures what is written to std::cerr (where OpenMesh's omerr() goes) while alive.
class CerrCapture {
public:
    CerrCapture() : m_previous(std::cerr.rdbuf(m_buffer.rdbuf())) {}
    ~CerrCapture() { std::cerr.rdbuf(m_previous); }
    CerrCapture(const CerrCapture&) = delete;
    CerrCapture& operator=(const CerrCapture&) = delete;
    [[nodiscard]] std::string text() const { return m_buffer.str(); }

private:
    std::ostringstream m_buffer;
    std::streambuf* m_previous;
};

// Three triangles around the edge 0–1: the third makes it non-manifold.
TriangleMesh threeFacesOnOneEdge()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    return mesh;
}

} // namespace

class TestOpenMeshAdapter : public QObject {
    Q_OBJECT
private slots:
    void closedMeshRoundTripsExactly();
    void nonManifoldFacesAreRejectedQuietly();
    void invalidFacesAreRejected();
    void unreferencedVerticesKeepTheirIndex();
};

void TestOpenMeshAdapter::closedMeshRoundTripsExactly()
{
    for (const char* file : {"meshes/cube.obj", "meshes/two_nodes.glb", "meshes/tetrahedron.off"}) {
        const TriangleMesh mesh = loadMesh(testDataPath(file));
        const OpenMeshConversion conversion = toOpenMesh(mesh);
        QCOMPARE(conversion.rejectedFaces, std::size_t(0));
        QCOMPARE(conversion.mesh.n_vertices(), mesh.vertexCount());
        QCOMPARE(conversion.mesh.n_faces(), mesh.triangleCount());
        for (const auto halfedge : conversion.mesh.halfedges())
            QVERIFY2(!halfedge.is_boundary(), file);
        const TriangleMesh back = fromOpenMesh(conversion.mesh);
        QVERIFY2(back.positions == mesh.positions, file);
        QVERIFY2(back.triangles == mesh.triangles, file);
    }
}

void TestOpenMeshAdapter::nonManifoldFacesAreRejectedQuietly()
{
    CerrCapture capture;
    const OpenMeshConversion conversion = toOpenMesh(threeFacesOnOneEdge());
    QCOMPARE(conversion.rejectedFaces, std::size_t(1));
    QCOMPARE(conversion.rejectedFaceIndices, (std::vector<std::size_t>{2}));
    QCOMPARE(conversion.mesh.n_faces(), std::size_t(2));
    const OpenMeshConversion pair = toOpenMesh(loadMesh(testDataPath("meshes/nonmanifold_pair.obj")));
    QVERIFY(pair.rejectedFaces > 0);
    QCOMPARE(pair.mesh.n_faces() + pair.rejectedFaces, std::size_t(24));
    QCOMPARE(capture.text(), std::string()); // nothing printed
}

void TestOpenMeshAdapter::invalidFacesAreRejected()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 0, 1}, {0, 1, 7}, {2, 1, 0}};
    CerrCapture capture;
    const OpenMeshConversion conversion = toOpenMesh(mesh);
    // The degenerate and the out-of-range face; the reversed copy of face 0 would reuse
    // its directed edges' opposites only, which a half-edge mesh allows (a closed sheet).
    QCOMPARE(conversion.rejectedFaceIndices, (std::vector<std::size_t>{1, 2}));
    QCOMPARE(capture.text(), std::string());
}

void TestOpenMeshAdapter::unreferencedVerticesKeepTheirIndex()
{
    TriangleMesh mesh;
    mesh.positions = {{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{1, 2, 3}};
    const TriangleMesh back = fromOpenMesh(toOpenMesh(mesh).mesh);
    QCOMPARE(back.positions, mesh.positions);
    QCOMPARE(back.triangles, mesh.triangles);
}

QTEST_APPLESS_MAIN(TestOpenMeshAdapter)
#include "tst_openmesh_adapter.moc"
