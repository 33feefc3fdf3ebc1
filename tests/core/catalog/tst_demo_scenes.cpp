// Demo scenes and shape generators: closed oriented 2-cycles, outward, deterministic,
// and the self-crossing demos really cross themselves.
#include "core/catalog/demo_scenes.h"
#include "core/catalog/demo_shapes.h"
#include "core/scene/shape_generators.h"
#include "core/trim/ray_triangle.h"
#include "core/trim/winding_number.h"

#include <glm/geometric.hpp>

#include <QtTest>

#include <algorithm>
#include <map>
#include <numbers>
#include <set>

using namespace trimlab;

namespace {

// Every directed edge used exactly once and its reverse exactly once; no triangle with a
// repeated index. Returns an empty string or the first problem found.
QString closedOrientedProblem(const TriangleMesh& mesh)
{
    std::map<std::pair<unsigned, unsigned>, int> directed;
    for (const glm::uvec3& t : mesh.triangles) {
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
            return "triangle with a repeated vertex";
        for (int k = 0; k < 3; ++k) {
            if (t[k] >= mesh.positions.size())
                return "index out of range";
            ++directed[{t[k], t[(k + 1) % 3]}];
        }
    }
    for (const auto& [edge, count] : directed) {
        if (count != 1)
            return QString("edge %1->%2 used %3 times").arg(edge.first).arg(edge.second).arg(count);
        const auto reverse = directed.find({edge.second, edge.first});
        if (reverse == directed.end() || reverse->second != 1)
            return QString("edge %1->%2 has no single reverse").arg(edge.first).arg(edge.second);
    }
    return {};
}

double signedVolume(const TriangleMesh& mesh)
{
    double v = 0.0;
    for (const glm::uvec3& t : mesh.triangles)
        v += glm::dot(glm::dvec3(mesh.positions[t[0]]),
                      glm::cross(glm::dvec3(mesh.positions[t[1]]), glm::dvec3(mesh.positions[t[2]])));
    return v / 6.0;
}

bool distinctPositions(const TriangleMesh& mesh)
{
    std::set<std::tuple<float, float, float>> seen;
    for (const glm::vec3& p : mesh.positions)
        seen.insert({p.x, p.y, p.z});
    return seen.size() == mesh.positions.size();
}

// Number of (edge, triangle) pairs, sharing no vertex, where the edge segment crosses the
// triangle: > 0 iff two non-adjacent triangles intersect (brute force, small meshes).
int edgeTriangleCrossings(const TriangleMesh& mesh)
{
    std::set<std::pair<unsigned, unsigned>> edges;
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    int crossings = 0;
    for (const auto& [i, j] : edges) {
        const glm::dvec3 p(mesh.positions[i]);
        const glm::dvec3 q(mesh.positions[j]);
        const WatertightRay ray = makeWatertightRay({p, q - p});
        for (const glm::uvec3& t : mesh.triangles) {
            if (t[0] == i || t[1] == i || t[2] == i || t[0] == j || t[1] == j || t[2] == j)
                continue;
            const auto hit = intersectTriangle(ray, glm::dvec3(mesh.positions[t[0]]), glm::dvec3(mesh.positions[t[1]]),
                                               glm::dvec3(mesh.positions[t[2]]));
            if (hit && hit->t > 0.0 && hit->t < 1.0)
                ++crossings;
        }
    }
    return crossings;
}

} // namespace

class TestDemoScenes : public QObject {
    Q_OBJECT
private slots:
    void namesAndDescriptions();
    void everyDemoIsClosedOrientedOutward_data();
    void everyDemoIsClosedOrientedOutward();
    void deterministic();
    void generatorsAreClosedAndOriented();
    void windingNumbersOfDemos();
    void selfCrossingDemosIntersectThemselves();
    void invalidGeneratorInputGivesEmptyMesh();
};

void TestDemoScenes::namesAndDescriptions()
{
    const std::vector<std::string> names = demoSceneNames();
    QCOMPARE(names,
             (std::vector<std::string>{"pushed-sphere", "crossing-loop", "nested-spheres", "sphere", "csg-trio"}));
    for (const std::string& name : names) {
        QVERIFY(!demoSceneDescription(name).empty());
        QVERIFY(demoSceneDescription(name).find('\n') == std::string_view::npos);
        QVERIFY(makeDemoScene(name).has_value());
    }
    QVERIFY(demoSceneDescription("teapot").empty());
    QVERIFY(!makeDemoScene("teapot").has_value());
    QVERIFY(!makeDemoScene("").has_value());
}

void TestDemoScenes::everyDemoIsClosedOrientedOutward_data()
{
    QTest::addColumn<QString>("name");
    for (const std::string& name : demoSceneNames())
        QTest::newRow(name.c_str()) << QString::fromStdString(name);
}

void TestDemoScenes::everyDemoIsClosedOrientedOutward()
{
    QFETCH(QString, name);
    const std::optional<Scene> scene = makeDemoScene(name.toStdString());
    QVERIFY(scene && !scene->objects.empty() && scene->objects.size() <= Scene::maxObjects);
    for (const SceneObject& object : scene->objects) {
        const QString problem = closedOrientedProblem(object.mesh);
        QVERIFY2(problem.isEmpty(), qPrintable(object.name.c_str() + QString(": ") + problem));
        QVERIFY2(signedVolume(object.mesh) > 0.0, object.name.c_str());
        QVERIFY2(distinctPositions(object.mesh), object.name.c_str());
        QVERIFY(object.modelMatrix == glm::dmat4(1.0));
        QVERIFY(object.mesh.triangleCount() >= 1000 && object.mesh.triangleCount() <= 20000);
        qInfo("%s/%s: %zu vertices, %zu triangles, signed volume %.4f", qPrintable(name), object.name.c_str(),
              object.mesh.vertexCount(), object.mesh.triangleCount(), signedVolume(object.mesh));
    }
    QVERIFY(scene->worldBounds().radius() < 2.5);
}

void TestDemoScenes::deterministic()
{
    for (const std::string& name : demoSceneNames()) {
        const Scene a = *makeDemoScene(name);
        const Scene b = *makeDemoScene(name);
        QCOMPARE(a.objects.size(), b.objects.size());
        for (std::size_t i = 0; i < a.objects.size(); ++i) {
            QVERIFY(a.objects[i].mesh.positions == b.objects[i].mesh.positions); // bitwise
            QVERIFY(a.objects[i].mesh.triangles == b.objects[i].mesh.triangles);
        }
    }
}

void TestDemoScenes::generatorsAreClosedAndOriented()
{
    const std::vector<glm::dvec3> circle = {{1, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, -1}};
    const TriangleMesh meshes[] = {
        makeUvSphere({1, 2, 3}, 0.5, 7, 9),     makeIcosphere({0, 1, 0}, 2.0, 2), makeTorus({0, 0, 1}, 2.0, 0.5, 17, 7),
        makeTube(lemniscateCurve(50), 0.25, 6), makeTube(circle, 0.3, 5),         makePushedSphere(12, 10),
    };
    for (const TriangleMesh& mesh : meshes) {
        QVERIFY(!mesh.empty());
        const QString problem = closedOrientedProblem(mesh);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QVERIFY(signedVolume(mesh) > 0.0);
        QVERIFY(distinctPositions(mesh));
    }
    // Counts from the headers.
    QCOMPARE(makeUvSphere({0, 0, 0}, 1.0, 7, 9).triangleCount(), std::size_t(2 * 9 * 6));
    QCOMPARE(makeIcosphere({0, 0, 0}, 1.0, 2).triangleCount(), std::size_t(20 * 16));
    QCOMPARE(makeTorus({0, 0, 0}, 2.0, 0.5, 17, 7).triangleCount(), std::size_t(2 * 17 * 7));
    QCOMPARE(makePushedSphere(12, 10).triangleCount(), std::size_t(2 * 12 * 8));
    // Inward versions have the opposite signed volume.
    const double out = signedVolume(makeIcosphere({0, 0, 0}, 1.0, 2));
    QCOMPARE(signedVolume(makeIcosphere({0, 0, 0}, 1.0, 2, false)), -out);
    QVERIFY(signedVolume(makeUvSphere({0, 0, 0}, 1.0, 8, 8, false)) < 0.0);
    QVERIFY(signedVolume(makeTorus({0, 0, 0}, 1.0, 0.3, 8, 8, false)) < 0.0);
    // A sphere volume close to 4π/3 r³.
    const double sphere = signedVolume(makeUvSphere({5, 0, 0}, 2.0, 64, 64));
    QVERIFY(std::abs(sphere - 4.0 / 3.0 * std::numbers::pi * 8.0) < 0.05 * sphere);
}

// Winding numbers derived by hand from the shapes (see demo_shapes.h), computed from
// solid angles, independent of any ray.
void TestDemoScenes::windingNumbersOfDemos()
{
    struct Probe {
        const char* scene;
        glm::dvec3 point;
        int w;
    };
    const Probe probes[] = {
        {"sphere", {0, 0, 0}, 1},
        {"sphere", {0, 0, 1.5}, 0},
        {"nested-spheres", {0, 0, 0}, 2},
        {"nested-spheres", {0.75, 0, 0}, 1},
        {"nested-spheres", {0, 2, 0}, 0},
        {"pushed-sphere", {0.65, 0, 0}, 1},   // body of the sphere
        {"pushed-sphere", {0, 0, 0}, 0},      // inside the finger, within the sphere
        {"pushed-sphere", {0, -1.3, 0}, -1},  // inside the finger, below the sphere
        {"pushed-sphere", {0, 1.5, 0}, 0},    // above
        {"crossing-loop", {0, 0, 0}, 2},      // the crossing
        {"crossing-loop", {1.6, 0, 0}, 1},    // in the tube
        {"crossing-loop", {0.8, 0, 0}, 0},    // the hole of a lobe
        {"crossing-loop", {-1.6, 0.1, 0}, 1}, // in the tube, other lobe
    };
    for (const Probe& probe : probes) {
        const double w = solidAngleWindingNumber(*makeDemoScene(probe.scene), probe.point);
        QVERIFY2(std::abs(w - probe.w) < 1e-6, qPrintable(QString("%1 at (%2, %3, %4): %5, expected %6")
                                                              .arg(probe.scene)
                                                              .arg(probe.point.x)
                                                              .arg(probe.point.y)
                                                              .arg(probe.point.z)
                                                              .arg(w)
                                                              .arg(probe.w)));
    }
}

void TestDemoScenes::selfCrossingDemosIntersectThemselves()
{
    const int pushed = edgeTriangleCrossings(makePushedSphere(16, 16));
    const int loop = edgeTriangleCrossings(makeCrossingLoop(40, 8));
    const int sphere = edgeTriangleCrossings(makeUvSphere({0, 0, 0}, 1.0, 10, 12));
    const int torus = edgeTriangleCrossings(makeTorus({0, 0, 0}, 1.0, 0.3, 24, 8));
    qInfo("edge-triangle crossings: pushed-sphere %d, crossing-loop %d, sphere %d, torus %d", pushed, loop, sphere,
          torus);
    QVERIFY(pushed > 0);
    QVERIFY(loop > 0);
    QCOMPARE(sphere, 0);
    QCOMPARE(torus, 0);
}

void TestDemoScenes::invalidGeneratorInputGivesEmptyMesh()
{
    QVERIFY(makeUvSphere({0, 0, 0}, 0.0, 8, 8).empty());
    QVERIFY(makeUvSphere({0, 0, 0}, 1.0, 1, 8).empty());
    QVERIFY(makeUvSphere({0, 0, 0}, 1.0, 8, 2).empty());
    QVERIFY(makeIcosphere({0, 0, 0}, -1.0, 2).empty());
    QVERIFY(makeIcosphere({0, 0, 0}, 1.0, 9).empty());
    QVERIFY(makeTorus({0, 0, 0}, 1.0, 1.0, 8, 8).empty());
    QVERIFY(makeTube(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}}, 0.1, 8).empty());
    QVERIFY(makeTube(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0.1, 8).empty());
    const std::vector<glm::dvec2> open = {{0.5, -1}, {1, 0}, {0, 1}};
    QVERIFY(makeSurfaceOfRevolution(open, 8).empty());
    const std::vector<glm::dvec2> onAxis = {{0, -1}, {0, 0}, {0, 1}};
    QVERIFY(makeSurfaceOfRevolution(onAxis, 8).empty());
}

QTEST_APPLESS_MAIN(TestDemoScenes)
#include "tst_demo_scenes.moc"
