// Loop subdivision through OpenSubdiv (core/mesh/loop_subdivision.h): counts, topology,
// orientation, and the positions against Loop's masks computed here by hand.
#include "core/mesh/loop_subdivision.h"

#include "core/mesh/mesh_validation.h"
#include "core/scene/shape_generators.h"

#include <QtTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <set>
#include <utility>

using namespace trimlab;

namespace {

// Loop's vertex mask for an interior vertex of valence n: (1 − nβ)·v + β·Σ neighbours,
// β = (5/8 − (3/8 + cos(2π/n)/4)²)/n.
glm::dvec3 loopVertexPoint(const TriangleMesh& mesh, std::uint32_t v)
{
    std::set<std::uint32_t> ring;
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (t[k] == v) {
                ring.insert(t[(k + 1) % 3]);
                ring.insert(t[(k + 2) % 3]);
            }
    const double n = double(ring.size());
    const double c = 0.375 + 0.25 * std::cos(2.0 * M_PI / n);
    const double beta = (0.625 - c * c) / n;
    glm::dvec3 sum(0.0);
    for (const std::uint32_t u : ring)
        sum += glm::dvec3(mesh.positions[u]);
    return (1.0 - n * beta) * glm::dvec3(mesh.positions[v]) + beta * sum;
}

// Loop's edge points 3/8·(a + b) + 1/8·(c + d) of every interior edge (a, b) with
// opposite corners c, d.
std::vector<glm::dvec3> loopEdgePoints(const TriangleMesh& mesh)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> opposite;
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[(k + 1) % 3], b = t[(k + 2) % 3];
            opposite[{std::min(a, b), std::max(a, b)}].push_back(t[k]);
        }
    std::vector<glm::dvec3> points;
    for (const auto& [edge, corners] : opposite) {
        if (corners.size() != 2)
            continue;
        const glm::dvec3 a(mesh.positions[edge.first]), b(mesh.positions[edge.second]);
        const glm::dvec3 c(mesh.positions[corners[0]]), d(mesh.positions[corners[1]]);
        points.push_back(0.375 * (a + b) + 0.125 * (c + d));
    }
    return points;
}

} // namespace

class TestLoopSubdivision : public QObject {
    Q_OBJECT
private slots:
    void levelZeroIsACopy();
    void icosahedronFollowsLoopsMasks();
    void twoLevelsKeepAClosedOrientedSurface();
    void openMeshesKeepTheirBoundary();
    void badInputIsRefused();
};

void TestLoopSubdivision::levelZeroIsACopy()
{
    const TriangleMesh ico = makeIcosphere({0, 0, 0}, 1.0, 0);
    QCOMPARE(loopSubdivide(ico, 0), ico);
}

void TestLoopSubdivision::icosahedronFollowsLoopsMasks()
{
    const TriangleMesh ico = makeIcosphere({1, 2, 3}, 2.0, 0);
    const TriangleMesh once = loopSubdivide(ico, 1);
    QCOMPARE(once.vertexCount(), std::size_t(12 + 30));
    QCOMPARE(once.triangleCount(), std::size_t(80));
    // The original vertices come first, moved by the vertex mask.
    for (std::uint32_t v = 0; v < 12; ++v)
        QVERIFY(glm::length(glm::dvec3(once.positions[v]) - loopVertexPoint(ico, v)) < 1e-6);
    // Every new vertex is the edge point of one edge, each edge used once.
    std::vector<glm::dvec3> edgePoints = loopEdgePoints(ico);
    QCOMPARE(edgePoints.size(), std::size_t(30));
    for (std::size_t v = 12; v < once.vertexCount(); ++v) {
        const auto match = std::find_if(edgePoints.begin(), edgePoints.end(), [&](const glm::dvec3& e) {
            return glm::length(e - glm::dvec3(once.positions[v])) < 1e-6;
        });
        QVERIFY2(match != edgePoints.end(), qPrintable(QString("vertex %1").arg(v)));
        edgePoints.erase(match);
    }
}

void TestLoopSubdivision::twoLevelsKeepAClosedOrientedSurface()
{
    const TriangleMesh torus = makeTorus({0, 0, 0}, 2.0, 0.5, 16, 8);
    const TriangleMesh twice = loopSubdivide(torus, 2);
    QCOMPARE(twice.triangleCount(), 16 * torus.triangleCount());
    const MeshValidationReport before = validateMesh(torus), after = validateMesh(twice);
    QVERIFY(after.trimmable());
    QVERIFY(after.manifold());
    QCOMPARE(after.genus, before.genus);
    QCOMPARE(*after.genus, std::int64_t(1));
    QVERIFY(after.signedVolume > 0.0);
    // V' = V + E per level; for a closed triangle mesh E = 3F/2.
    const std::size_t v1 = torus.vertexCount() + 3 * torus.triangleCount() / 2;
    QCOMPARE(twice.vertexCount(), v1 + 3 * (4 * torus.triangleCount()) / 2);
    // Loop's masks have positive weights: every new point is an average of nearby
    // points of the (16×8-gon) tube, so its distance from the core circle can change at
    // most by how far a chord of the 8-gon section (0.5·(1 − cos π/8) ≈ 0.04) and of the
    // 16-gon rings (2.5·(1 − cos π/8) ≈ 0.19 outside, 1.5·(1 − cos π/8) ≈ 0.11 inside)
    // sags: r ∈ [0.5 − 0.04 − 0.19, 0.5 + 0.11].
    for (const glm::vec3& p : twice.positions) {
        const double ring = std::hypot(double(p.x), double(p.z)) - 2.0;
        const double r = std::hypot(ring, double(p.y));
        QVERIFY2(r > 0.26 && r < 0.62, qPrintable(QString::number(r)));
    }
}

void TestLoopSubdivision::openMeshesKeepTheirBoundary()
{
    TriangleMesh strip;
    strip.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    strip.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
    const TriangleMesh once = loopSubdivide(strip, 1);
    QCOMPARE(once.triangleCount(), std::size_t(16));
    const MeshValidationReport report = validateMesh(once);
    QCOMPARE(report.boundaryEdges.count, std::size_t(2 * 6)); // each of the 6 boundary edges split
    for (const glm::vec3& p : once.positions)
        QCOMPARE(p.z, 0.0f); // a planar mesh stays in its plane
}

void TestLoopSubdivision::badInputIsRefused()
{
    const TriangleMesh ico = makeIcosphere({0, 0, 0}, 1.0, 0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)loopSubdivide(ico, -1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)loopSubdivide(ico, 16));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)loopSubdivide(ico, 12)); // 20·4¹² triangles
    TriangleMesh repeated = ico;
    repeated.triangles[3].y = repeated.triangles[3].x;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)loopSubdivide(repeated, 1));
    TriangleMesh nan = ico;
    nan.positions[2].x = std::nanf("");
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)loopSubdivide(nan, 1));
}

QTEST_GUILESS_MAIN(TestLoopSubdivision)
#include "tst_loop_subdivision.moc"
