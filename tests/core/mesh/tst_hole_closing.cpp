// Closing a mesh's holes by fans (core/mesh/boundary_loops, hole_fans) and an animation's
// holes in every pose (core/animation/closed_animation): the closed mesh is a closed,
// consistently oriented manifold with the Euler characteristic of the surface without
// holes, and every pose gets the same new triangles with its own centroids.
#include "core/animation/closed_animation.h"
#include "core/mesh/boundary_loops.h"
#include "core/mesh/hole_fans.h"
#include "core/mesh/mesh_validation.h"
#include "core/scene/shape_generators.h"

#include <QtTest>

using namespace trimlab;

namespace {

// An icosphere with two triangles that share no vertex removed: two holes of 3 edges.
TriangleMesh holedSphere()
{
    TriangleMesh mesh = makeIcosphere(glm::dvec3(0.0), 1.0, 1);
    const glm::uvec3 first = mesh.triangles.front();
    auto sharesVertex = [&](const glm::uvec3& t) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (t[i] == first[j])
                    return true;
        return false;
    };
    std::size_t far = 1;
    while (sharesVertex(mesh.triangles[far]))
        ++far;
    mesh.triangles.erase(mesh.triangles.begin() + std::ptrdiff_t(far));
    mesh.triangles.erase(mesh.triangles.begin());
    return mesh;
}

// An open cylinder of `sides` quads around z in [0, 1]: two loops of `sides` edges,
// outward normals.
TriangleMesh openCylinder(std::uint32_t sides)
{
    TriangleMesh mesh;
    for (std::uint32_t ring = 0; ring < 2; ++ring)
        for (std::uint32_t s = 0; s < sides; ++s) {
            const float angle = 2.0f * 3.14159265f * float(s) / float(sides);
            mesh.positions.emplace_back(std::cos(angle), std::sin(angle), float(ring));
        }
    for (std::uint32_t s = 0; s < sides; ++s) {
        const std::uint32_t n = (s + 1) % sides;
        mesh.triangles.emplace_back(s, n, sides + n);
        mesh.triangles.emplace_back(s, sides + n, sides + s);
    }
    return mesh;
}

void requireClosedSphere(const TriangleMesh& mesh)
{
    const MeshValidationReport report = validateMesh(mesh);
    QVERIFY(report.closed());
    QVERIFY(report.manifold());
    QVERIFY2(report.trimmable(), report.trimUnavailableReason().c_str());
    QCOMPARE(report.eulerCharacteristic.value(), std::int64_t(2));
    QCOMPARE(report.genus.value(), std::int64_t(0));
    QVERIFY(report.signedVolume > 0.0);
}

} // namespace

class TestHoleClosing : public QObject {
    Q_OBJECT
private slots:
    void loopsRunAgainstTheMesh();
    void holedSphereBecomesASphere();
    void cylinderGetsTwoCaps();
    void closedMeshIsUnchanged();
    void everyPoseGetsTheSameFans();
    void inconsistentBoundaryIsRefused();
};

void TestHoleClosing::loopsRunAgainstTheMesh()
{
    const TriangleMesh mesh = openCylinder(5);
    const auto loops = boundaryLoops(mesh.triangles);
    QCOMPARE(loops.size(), std::size_t(2));
    // The bottom ring's triangles use s -> s+1, so the loop runs s+1 -> s.
    QCOMPARE(loops[0], (std::vector<std::uint32_t>{0, 4, 3, 2, 1}));
    QCOMPARE(loops[1], (std::vector<std::uint32_t>{5, 6, 7, 8, 9}));
}

void TestHoleClosing::holedSphereBecomesASphere()
{
    const TriangleMesh open = holedSphere();
    QCOMPARE(validateMesh(open).boundaryEdges.count, std::size_t(6));
    const TriangleMesh closed = closeHoles(open);
    QCOMPARE(closed.vertexCount(), open.vertexCount() + 2);
    QCOMPARE(closed.triangleCount(), open.triangleCount() + 6);
    requireClosedSphere(closed);
}

void TestHoleClosing::cylinderGetsTwoCaps()
{
    const TriangleMesh closed = closeHoles(openCylinder(8));
    requireClosedSphere(closed);
    // The centres: the bottom loop's (vertex 16) on the axis at z = 0, the top's at z = 1.
    QVERIFY(std::abs(closed.positions[16].x) < 1e-6f && std::abs(closed.positions[16].y) < 1e-6f);
    QCOMPARE(closed.positions[16].z, 0.0f);
    QCOMPARE(closed.positions[17].z, 1.0f);
}

void TestHoleClosing::closedMeshIsUnchanged()
{
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 1);
    QVERIFY(holeFans(sphere.triangles, sphere.vertexCount()).empty());
    QCOMPARE(closeHoles(sphere), sphere);
}

void TestHoleClosing::everyPoseGetsTheSameFans()
{
    const TriangleMesh open = holedSphere();
    MeshAnimation animation;
    animation.triangles = open.triangles;
    animation.poses.push_back(open.positions);
    std::vector<glm::vec3> moved = open.positions;
    for (glm::vec3& p : moved)
        p = p * glm::vec3(2.0f, 1.0f, 0.5f) + glm::vec3(3.0f, 0.0f, 0.0f);
    animation.poses.push_back(moved);

    const MeshAnimation closed = closeAnimationHoles(animation);
    requireWellFormed(closed);
    const HoleFans fans = holeFans(open.triangles, open.vertexCount());
    QCOMPARE(fans.loops.size(), std::size_t(2));
    QCOMPARE(closed.triangleCount(), open.triangleCount() + fans.triangles.size());
    for (std::size_t pose = 0; pose < 2; ++pose) {
        requireClosedSphere(closed.poseMesh(pose));
        for (std::size_t l = 0; l < fans.loops.size(); ++l) {
            glm::dvec3 centroid(0.0);
            for (std::uint32_t v : fans.loops[l])
                centroid += glm::dvec3(animation.poses[pose][v]);
            centroid /= double(fans.loops[l].size());
            QCOMPARE(closed.poses[pose][fans.firstCentre + l], glm::vec3(centroid));
        }
    }
}

void TestHoleClosing::inconsistentBoundaryIsRefused()
{
    // Two triangles sharing the edge 1-2 in the same direction: the edge is used twice
    // (not boundary) and the boundary path 0 -> ... cannot return.
    const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {3, 1, 2}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)boundaryLoops(triangles));
}

QTEST_APPLESS_MAIN(TestHoleClosing)
#include "tst_hole_closing.moc"
