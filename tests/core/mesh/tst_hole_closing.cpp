// Closing a mesh's holes by fans (core/mesh/boundary_loops, hole_fans) and an animation's
// holes in every pose (core/animation/closed_animation): the closed mesh is a closed,
// consistently oriented manifold with the Euler characteristic of the surface without
// holes, and every pose gets the same new triangles with its own centroids. A fan that
// passes through the surface is reported (core/trim/hole_closing), in a mesh, in the pose
// of an animation and in the object of a scene where it happens.
#include "core/animation/closed_animation.h"
#include "core/catalog/closed_scene.h"
#include "core/mesh/mesh_load_error.h"
#include "core/mesh/boundary_loops.h"
#include "core/mesh/hole_fans.h"
#include "core/mesh/mesh_validation.h"
#include "core/scene/shape_generators.h"
#include "core/trim/hole_closing.h"

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

// A small tetrahedron (its own component) around the axis, straddling the plane z = 1 of
// openCylinder's top loop: the top loop's fan passes through its faces.
void addTetrahedronThroughTheTop(TriangleMesh& mesh)
{
    const auto first = std::uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {{0.0f, 0.0f, 0.8f}, {0.2f, 0.0f, 1.2f}, {-0.1f, 0.17f, 1.2f}, {-0.1f, -0.17f, 1.2f}});
    for (const glm::uvec3& t : {glm::uvec3(0, 2, 1), glm::uvec3(0, 3, 2), glm::uvec3(0, 1, 3), glm::uvec3(1, 2, 3)})
        mesh.triangles.push_back(t + first);
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
    void closedMeshSaysWhatItClosed();
    void aFanThroughTheSurfaceIsReported();
    void thePoseWhereAFanCrossesIsNamed();
    void aSceneIsClosedObjectByObject();
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
    const TriangleMesh closed = closedMesh(openCylinder(8)); // the rim's walls do not count as crossings
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

void TestHoleClosing::closedMeshSaysWhatItClosed()
{
    const TriangleMesh open = holedSphere();
    HoleClosing closing;
    const TriangleMesh closed = closedMesh(open, &closing);
    QCOMPARE(closed, closeHoles(open));
    QCOMPARE(closing.holes, std::size_t(2));
    QCOMPARE(closing.edges, std::size_t(6));
    QCOMPARE(holeClosingText(closing), std::string("2 holes of 6 edges"));
    QCOMPARE(holeClosingText(HoleClosing{1, 20, {}, 0}), std::string("1 hole of 20 edges"));
    const TriangleMesh sphere = makeIcosphere(glm::dvec3(0.0), 1.0, 1);
    QCOMPARE(closedMesh(sphere, &closing), sphere);
    QCOMPARE(holeClosingText(closing), std::string("no holes"));
}

// The top fan cuts the tetrahedron: the points of the tetrahedron above the cap get
// winding number 2 or 0 instead of 1. The bottom hole is far from it; the warning names
// the top one (8 edges, first corner 8) and a triangle of the tetrahedron (16 to 19).
void TestHoleClosing::aFanThroughTheSurfaceIsReported()
{
    TriangleMesh mesh = openCylinder(8);
    addTetrahedronThroughTheTop(mesh);
    const HoleFans fans = holeFans(mesh.triangles, mesh.vertexCount());
    const std::optional<FanCrossing> crossing =
        firstFanCrossing(fans, mesh.triangles, withHoleCentres(fans, mesh.positions));
    QVERIFY(crossing);
    QCOMPARE(crossing->loop, std::size_t(1));
    QVERIFY(crossing->meshTriangle >= 16 && crossing->meshTriangle < 20);
    HoleClosing closing;
    QCOMPARE(closedMesh(mesh, &closing, "here: "), closeHoles(mesh)); // applied all the same
    QCOMPARE(closing.crossingMeshes, std::size_t(1));
    QVERIFY2(closing.crossing.starts_with("here: the fan closing the hole of 8 edges at vertex 8 crosses triangle 1"),
             closing.crossing.c_str());
    QVERIFY2(holeClosingText(closing).find("2 holes of 16 edges; warning: here: the fan closing") == 0,
             holeClosingText(closing).c_str());
    // Lowered below the rim, the tetrahedron is clear of the cap.
    for (std::size_t v = 16; v < 20; ++v)
        mesh.positions[v].z -= 0.5f;
    QVERIFY(!firstFanCrossing(fans, mesh.triangles, withHoleCentres(fans, mesh.positions)));
    (void)closedMesh(mesh, &closing);
    QVERIFY(closing.crossing.empty() && closing.crossingMeshes == 0);
}

// Pose 0 has the tetrahedron inside the cylinder, pose 1 lifts it through the top loop.
void TestHoleClosing::thePoseWhereAFanCrossesIsNamed()
{
    TriangleMesh mesh = openCylinder(8);
    addTetrahedronThroughTheTop(mesh);
    MeshAnimation animation;
    animation.triangles = mesh.triangles;
    std::vector<glm::vec3> inside = mesh.positions;
    for (std::size_t v = 16; v < 20; ++v)
        inside[v].z -= 0.5f;
    animation.poses = {inside, mesh.positions};
    animation.poses.push_back(inside);
    HoleClosing closing;
    (void)closeAnimationHoles(animation, &closing);
    QCOMPARE(closing.crossingMeshes, std::size_t(1));
    QVERIFY2(closing.crossing.starts_with("pose 1: the fan closing the hole of 8 edges"), closing.crossing.c_str());
    animation.poses.pop_back();
    animation.poses.pop_back();
    const MeshAnimation closed = closeAnimationHoles(animation, &closing);
    QCOMPARE(closing.holes, std::size_t(2));
    QVERIFY(closing.crossing.empty());
    QCOMPARE(closed.triangleCount(), mesh.triangleCount() + 16);
}

// A scene of a holed sphere and a closed one: the holed object is closed and its report
// redone (trimmable now), the closed one untouched; a fan that crosses its object is
// reported with the object's name.
void TestHoleClosing::aSceneIsClosedObjectByObject()
{
    LoadedScene loaded;
    loaded.source = "two.obj";
    loaded.scene.objects.push_back({"holed", holedSphere(), glm::dmat4(1.0)});
    loaded.scene.objects.push_back({"whole", makeIcosphere(glm::dvec3(3.0, 0.0, 0.0), 1.0, 1), glm::dmat4(1.0)});
    for (const SceneObject& object : loaded.scene.objects)
        loaded.reports.push_back(validateMesh(object.mesh));
    QVERIFY(!loaded.trimmable());
    const TriangleMesh whole = loaded.scene.objects[1].mesh;
    const HoleClosing closing = closeSceneHoles(loaded);
    QCOMPARE(closing.holes, std::size_t(2));
    QVERIFY2(loaded.trimmable(), loaded.trimUnavailableReason().c_str());
    QCOMPARE(loaded.scene.objects[1].mesh, whole);

    TriangleMesh crossing = openCylinder(8);
    addTetrahedronThroughTheTop(crossing);
    loaded.scene.objects.push_back({"tube", crossing, glm::dmat4(1.0)});
    loaded.reports.push_back(validateMesh(crossing));
    const HoleClosing withCrossing = closeSceneHoles(loaded);
    QVERIFY2(withCrossing.crossing.starts_with("object 'tube': the fan closing"), withCrossing.crossing.c_str());
    QVERIFY(loaded.reports.back().closed());

    // A boundary that forms no loops is refused naming the source and the object, and the
    // scene stays as it was.
    TriangleMesh fold;
    fold.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
    fold.triangles = {{0, 1, 2}, {3, 1, 2}};
    loaded.scene.objects.push_back({"fold", fold, glm::dmat4(1.0)});
    loaded.reports.push_back(validateMesh(fold));
    const TriangleMesh tube = loaded.scene.objects[2].mesh;
    try {
        (void)closeSceneHoles(loaded);
        QFAIL("a boundary without loops was closed");
    } catch (const MeshLoadError& e) {
        QCOMPARE(e.file(), std::string("two.obj"));
        QVERIFY2(e.reason().starts_with("object 'fold': cannot close its holes"), e.what());
    }
    QCOMPARE(loaded.scene.objects[2].mesh, tube);
}

QTEST_APPLESS_MAIN(TestHoleClosing)
#include "tst_hole_closing.moc"
