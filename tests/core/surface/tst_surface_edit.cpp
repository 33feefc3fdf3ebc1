// Control-point edits of editable surfaces (NURBS, subdivision) as timeline frames:
// exactly the changed vertices, exact reconstruction and undo, the control-point brush,
// and the surface scene sources.
#include "core/deform/falloff.h"
#include "core/mesh/mesh_load_error.h"
#include "core/catalog/scene_source.h"
#include "core/design/control_brush.h"
#include "core/timeline/control_edit.h"
#include "core/catalog/fig8_13_history.h"
#include "core/surface/nurbs_json.h"
#include "core/surface/nurbs_primitives.h"
#include "core/surface/subdivision_cages.h"
#include "core/catalog/surface_scenes.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>

using namespace trimlab;

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameFloatBits(const glm::vec3& a, const glm::vec3& b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

SurfaceDefinition sphereDefinition()
{
    return nurbsDefinition(makeNurbsSphere(glm::dvec3(0.0), 1.0), 24, 12);
}

SurfaceDefinition cubeDefinition(SubdivisionMode mode)
{
    return subdivisionDefinition(cubeCage(1.0), SubdivisionSettings{2, mode});
}

// Every vertex whose bits differ between two position arrays, by brute force.
std::vector<std::uint32_t> changedVertices(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b)
{
    std::vector<std::uint32_t> changed;
    for (std::size_t v = 0; v < a.size(); ++v)
        if (!sameFloatBits(a[v], b[v]))
            changed.push_back(std::uint32_t(v));
    return changed;
}

} // namespace

class TestSurfaceEdit : public QObject {
    Q_OBJECT
private slots:
    void controlEditFrameListsExactlyTheChangedVertices_data();
    void controlEditFrameListsExactlyTheChangedVertices();
    void tiedNurbsPointsMoveTogether();
    void historyReconstructsExactlyAndUndoRestores();
    void timelineRefusesBadControlMoves();
    void editableSurfaceRefusesBadDefinitions();
    void brushMovesOnlyPointsWithinTheRadius();
    void translateAndNormalMoves();
    void netEdges();
    void sceneSources();
};

void TestSurfaceEdit::controlEditFrameListsExactlyTheChangedVertices_data()
{
    QTest::addColumn<int>("kind");
    QTest::newRow("nurbs sphere") << 0;
    QTest::newRow("subdivision limit") << 1;
    QTest::newRow("subdivision uniform") << 2;
}

void TestSurfaceEdit::controlEditFrameListsExactlyTheChangedVertices()
{
    QFETCH(int, kind);
    const SurfaceDefinition definition = kind == 0   ? sphereDefinition()
                                         : kind == 1 ? cubeDefinition(SubdivisionMode::Limit)
                                                     : cubeDefinition(SubdivisionMode::Uniform);
    EditableSurface surface(definition);
    const std::vector<glm::vec3> before = surface.mesh().positions;
    const std::uint32_t moved = kind == 0 ? std::uint32_t(definition.nurbs().surface.index(2, 2)) : 3u;
    const ControlPointTarget target{moved, surface.controlPoints()[moved] + glm::dvec3(0.3, -0.2, 0.1)};
    const timeline::Frame frame = controlEditFrame(surface, std::span(&target, 1), before);

    const std::vector<glm::vec3>& after = surface.mesh().positions;
    QCOMPARE(frame.vertices, changedVertices(before, after));
    QVERIFY(!frame.vertices.empty());
    QVERIFY(frame.vertices.size() < before.size()); // local support: not every vertex moved
    for (std::size_t k = 0; k < frame.vertices.size(); ++k) {
        QVERIFY(sameFloatBits(frame.before[k], before[frame.vertices[k]]));
        QVERIFY(sameFloatBits(frame.after[k], after[frame.vertices[k]]));
    }
    const std::vector<std::uint32_t> support = surface.support(moved);
    for (const std::uint32_t v : frame.vertices)
        QVERIFY(std::binary_search(support.begin(), support.end(), v));
    QVERIFY(frame.isControlEdit());
    QCOMPARE(frame.controlMoves.front().index, moved);
    QCOMPARE(frame.controlMoves.front().before, definition.controlPoints()[moved]);
    QCOMPARE(frame.controlMoves.front().after, target.position);
    // The sparse re-evaluation equals a full one, bit for bit.
    EditableSurface full(definition);
    full.setControlPoints(surface.controlPoints());
    QVERIFY(sameBytes(full.mesh().positions, after));
}

void TestSurfaceEdit::tiedNurbsPointsMoveTogether()
{
    const SurfaceDefinition definition = sphereDefinition();
    const NurbsSurface& net = definition.nurbs().surface;
    EditableSurface surface(definition);
    // The north pole: row 4, nine tied points; the seam: column 0 and column 8.
    const auto pole = std::uint32_t(net.index(3, 4));
    const ControlPointTarget push{pole, glm::dvec3(0.0, 0.4, 0.0)};
    const timeline::Frame frame = controlEditFrame(surface, std::span(&push, 1), surface.mesh().positions);
    QCOMPARE(frame.controlMoves.size(), std::size_t(9));
    for (int i = 0; i < 9; ++i) {
        QCOMPARE(frame.controlMoves[std::size_t(i)].index, std::uint32_t(net.index(i, 4)));
        QCOMPARE(frame.controlMoves[std::size_t(i)].after, glm::dvec3(0.0, 0.4, 0.0));
    }
    EditableSurface seam(definition);
    const ControlPointTarget twin{std::uint32_t(net.index(8, 2)), glm::dvec3(1.5, 0.0, 0.0)};
    const timeline::Frame seamFrame = controlEditFrame(seam, std::span(&twin, 1), seam.mesh().positions);
    QCOMPARE(seamFrame.controlMoves.size(), std::size_t(2));
    QCOMPARE(seamFrame.controlMoves[0].index, std::uint32_t(net.index(0, 2)));
    QCOMPARE(seamFrame.controlMoves[1].index, std::uint32_t(net.index(8, 2)));
    // Conflicting targets through a tie are refused, the surface unchanged.
    const std::vector<ControlPointTarget> conflict{{std::uint32_t(net.index(0, 4)), glm::dvec3(0.0, 0.5, 0.0)},
                                                   {std::uint32_t(net.index(5, 4)), glm::dvec3(0.0, 0.6, 0.0)}};
    const std::vector<glm::dvec3> kept = seam.controlPoints();
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)controlEditFrame(seam, conflict, seam.mesh().positions));
    QVERIFY(sameBytes(seam.controlPoints(), kept));
    // A target where the point already is: nothing moves.
    const ControlPointTarget still{0, seam.controlPoints()[0]};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             (void)controlEditFrame(seam, std::span(&still, 1), seam.mesh().positions));
}

void TestSurfaceEdit::historyReconstructsExactlyAndUndoRestores()
{
    timeline::Timeline history = fig8_13NurbsHistory(DynamicRule::Confluent, DynamicRule::ConstructiveSubtractive);
    QCOMPARE(history.frameCount(), 5);
    QCOMPARE(history.sets().size(), std::size_t(2));
    QCOMPARE(history.sets()[1].rule, DynamicRule::ConstructiveSubtractive);
    QCOMPARE(history.sets()[1].firstFrame, 2);
    EditableSurface surface(*history.surface());
    requireSurfaceMatchesTimeline(surface, history);
    std::vector<std::vector<glm::vec3>> positions;
    std::vector<std::vector<glm::dvec3>> controls;
    for (int f = 0; f < history.frameCount(); ++f) {
        // Each frame's positions are what the surface evaluates at its control points.
        surface.setControlPoints(history.controlPointsAt(f));
        QVERIFY2(sameBytes(history.positionsAt(f), surface.mesh().positions), qPrintable(QString("frame %1").arg(f)));
        positions.push_back(history.positionsAt(f));
        controls.push_back(history.controlPointsAt(f));
        if (f > 0) {
            QVERIFY(history.frame(f).isControlEdit());
            qInfo("frame %d: %zu control points and %zu of %zu vertices moved", f, history.frame(f).controlMoves.size(),
                  history.frame(f).vertices.size(), history.base().positions.size());
        }
    }
    QVERIFY(sameBytes(history.currentControlPoints(), controls.back()));
    const std::size_t northPole = 4 * 9; // index(0, 4) of the 9×5 net
    QCOMPARE(history.currentControlPoints()[northPole], glm::dvec3(0.0, -1.7, 0.0));
    // Undo frame by frame: the current state is the earlier frame's, bit for bit.
    for (int f = history.frameCount() - 2; f >= 0; --f) {
        const timeline::Frame removed = history.removeLastFrame();
        QVERIFY(removed.isControlEdit());
        QVERIFY(sameBytes(history.currentPositions(), positions[std::size_t(f)]));
        QVERIFY(sameBytes(history.currentControlPoints(), controls[std::size_t(f)]));
    }
    QVERIFY(sameBytes(history.currentControlPoints(), history.surface()->controlPoints()));
}

void TestSurfaceEdit::timelineRefusesBadControlMoves()
{
    const SurfaceDefinition definition = sphereDefinition();
    timeline::Timeline history = surfaceTimeline(definition);
    const std::vector<glm::dvec3> points = definition.controlPoints();
    const auto refuse = [&](std::vector<timeline::ControlPointMove> moves, const QString& expected) {
        timeline::Frame frame;
        frame.controlMoves = std::move(moves);
        try {
            history.appendFrame(frame);
        } catch (const std::invalid_argument& error) {
            QCOMPARE(QString(error.what()), expected);
            QCOMPARE(history.frameCount(), 1);
            return;
        }
        QFAIL(qPrintable("accepted: " + expected));
    };
    const std::uint32_t c = std::uint32_t(definition.nurbs().surface.index(2, 2));
    const glm::dvec3 p = points[c];
    refuse(
        {{c, p, p + glm::dvec3(1.0)}, {c, p, p}},
        QString("control move 1: the control points are not sorted ascending and unique: %1 is followed by %1").arg(c));
    refuse({{45, p, p}}, "control move 0: control point 45 is out of range (the surface has 45 control points)");
    refuse({{c, p + glm::dvec3(0.5, 0.0, 0.0), p}},
           QString("control move 0: the 'before' position (%1, %2, %3) of control point %4 differs from its current "
                   "position (%5, %2, %3)")
               .arg(QString::fromStdString(std::to_string(p.x + 0.5)), QString::fromStdString(std::to_string(p.y)),
                    QString::fromStdString(std::to_string(p.z)), QString::number(c),
                    QString::fromStdString(std::to_string(p.x))));
    refuse({{c, p, glm::dvec3(std::nan(""), 0.0, 0.0)}},
           QString("control move 0: the 'after' position of control point %1 is not finite").arg(c));
    // The pole point 36 alone: its eight tied points would stay behind.
    refuse({{36, points[36], glm::dvec3(0.0, 0.5, 0.0)}},
           "control move 0: control point 36 is tied to control point 37 (a seam twin or the same pole), which must "
           "move with it");
    // A brush stroke on the mesh of a surface history would detach the mesh from its control points.
    try {
        history.appendFrame(timeline::Frame{});
        QFAIL("a stroke frame was accepted on a surface history");
    } catch (const std::invalid_argument& error) {
        QCOMPARE(QString(error.what()), QString("this history edits a nurbs surface through its control points; a "
                                                "brush stroke on its mesh would break that (use the control-point "
                                                "brush)"));
    }
    // A plain mesh history has no control points.
    timeline::Timeline plain(EditableSurface(definition).mesh());
    timeline::Frame frame;
    frame.controlMoves = {{c, p, p}};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, plain.appendFrame(frame));
    QVERIFY(plain.controlPointsAt(0).empty());
}

void TestSurfaceEdit::editableSurfaceRefusesBadDefinitions()
{
    SurfaceDefinition bad = sphereDefinition();
    std::get<NurbsDefinition>(bad.source).surface.weights[17] = -1.0;
    try {
        EditableSurface surface(bad);
        QFAIL("a negative weight was accepted");
    } catch (const std::invalid_argument& error) {
        QVERIFY2(QString(error.what()).startsWith("EditableSurface: NURBS: weights[17]"), error.what());
    }
    SurfaceDefinition segments = sphereDefinition();
    std::get<NurbsDefinition>(segments.source).segmentsU = 0;
    QCOMPARE(findSurfaceDefinitionProblem(segments),
             std::optional<std::string>("NURBS: segmentsU 0 is outside 1 to 8192"));
    SurfaceDefinition level = cubeDefinition(SubdivisionMode::Limit);
    std::get<SubdivisionDefinition>(level.source).settings.level = 9;
    QCOMPARE(findSurfaceDefinitionProblem(level), std::optional<std::string>("subdivision: level 9 is outside 0 to 5"));
    SurfaceDefinition cage = cubeDefinition(SubdivisionMode::Limit);
    std::get<SubdivisionDefinition>(cage.source).cage.faceIndices[0] = 99;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, EditableSurface{cage});
    EditableSurface ok(sphereDefinition());
    const std::vector<glm::dvec3> wrongCount(3, glm::dvec3(0.0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ok.setControlPoints(wrongCount));
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, (void)ok.support(45));
}

void TestSurfaceEdit::brushMovesOnlyPointsWithinTheRadius()
{
    // Points on the x axis at known distances from the anchor (origin).
    const std::vector<glm::dvec3> points{{0.0, 0.0, 0.0},  {0.25, 0.0, 0.0}, {0.5, 0.0, 0.0},
                                         {0.99, 0.0, 0.0}, {1.0, 0.0, 0.0},  {2.0, 0.0, 0.0}};
    deform::BrushSettings brush;
    brush.radius = 1.0;
    brush.strength = 0.5;
    brush.profile = deform::FalloffProfile::Smooth;
    const glm::dvec3 drag(0.0, 2.0, 0.0);
    const std::vector<ControlPointTarget> targets = controlBrushTargets(points, glm::dvec3(0.0), drag, brush);
    QCOMPARE(targets.size(), std::size_t(4)); // 1.0 and 2.0 are at or beyond the radius
    for (const ControlPointTarget& t : targets) {
        const double x = points[t.index].x;
        const double smooth = (1.0 - x * x) * (1.0 - x * x); // the Smooth profile, written out
        QCOMPARE(t.position.x, x);
        QVERIFY2(std::abs(t.position.y - smooth * 0.5 * 2.0) < 1e-15, qPrintable(QString::number(t.position.y)));
    }
    QCOMPARE(targets[0].position, glm::dvec3(0.0, 1.0, 0.0)); // the anchor: strength × drag
    // The nearest point decides whether a radius reaches any: none within 0.2 of (2.2, 0, 0).
    QCOMPARE(nearestControlPointDistance(points, glm::dvec3(2.2, 0.0, 0.0)), 2.2 - 2.0);
    QCOMPARE(nearestControlPointDistance(points, glm::dvec3(0.5, 0.0, 0.0)), 0.0);
    QVERIFY(std::isinf(nearestControlPointDistance({}, glm::dvec3(0.0))));
    brush.radius = 0.2;
    QVERIFY(controlBrushTargets(points, glm::dvec3(2.2, 0.0, 0.0), drag, brush).empty());
    brush.radius = 0.21;
    QCOMPARE(controlBrushTargets(points, glm::dvec3(2.2, 0.0, 0.0), drag, brush).size(), std::size_t(1));
    brush.radius = 0.0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)controlBrushTargets(points, glm::dvec3(0.0), drag, brush));
    // On a sphere: only control points within the radius move, and the edit is a frame.
    const SurfaceDefinition definition = sphereDefinition();
    timeline::Timeline history = surfaceTimeline(definition);
    EditableSurface surface(definition);
    brush.radius = 0.8;
    brush.strength = 1.0;
    const glm::dvec3 anchor(1.0, 0.0, 0.0);
    const std::vector<ControlPointTarget> onSphere =
        controlBrushTargets(surface.controlPoints(), anchor, glm::dvec3(0.3, 0.0, 0.0), brush);
    QVERIFY(!onSphere.empty());
    for (const ControlPointTarget& t : onSphere)
        QVERIFY(glm::length(surface.controlPoints()[t.index] - anchor) < 0.8);
    appendControlEdit(history, surface, onSphere);
    QCOMPARE(history.frameCount(), 2);
    QCOMPARE(history.frame(1).controlMoves.size(), onSphere.size());
}

void TestSurfaceEdit::translateAndNormalMoves()
{
    const SurfaceDefinition definition = sphereDefinition();
    const NurbsSurface& net = definition.nurbs().surface;
    EditableSurface surface(definition);
    const std::vector<std::uint32_t> selection{std::uint32_t(net.index(0, 2)), std::uint32_t(net.index(0, 2))};
    const std::vector<ControlPointTarget> moved = translateControlPoints(surface, selection, glm::dvec3(0.0, 0.1, 0.0));
    QCOMPARE(moved.size(), std::size_t(2)); // the point and its seam twin (index(8, 2))
    QCOMPARE(moved[1].index, std::uint32_t(net.index(8, 2)));
    QCOMPARE(moved[0].position, surface.controlPoints()[moved[0].index] + glm::dvec3(0.0, 0.1, 0.0));
    // The equator point at +x: its normal is +x (the sphere is symmetric about z = 0).
    const glm::dvec3 n = surface.controlPointNormal(std::uint32_t(net.index(0, 2)));
    QVERIFY2(n.x > 0.99 && std::abs(n.y) < 1e-6, qPrintable(QString("%1 %2 %3").arg(n.x).arg(n.y).arg(n.z)));
    const std::vector<ControlPointTarget> out =
        moveControlPointsAlongNormal(surface, std::vector<std::uint32_t>{std::uint32_t(net.index(0, 2))}, 0.25);
    QCOMPARE(out.size(), std::size_t(2));
    QVERIFY(std::abs(out[0].position.x - 1.25) < 1e-6);
    const std::vector<std::uint32_t> outOfRange{45};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, (void)translateControlPoints(surface, outOfRange, glm::dvec3(1.0)));
}

void TestSurfaceEdit::netEdges()
{
    // 9×5 grid: 8·5 u-edges + 9·4 v-edges, minus the 2·8 edges inside the two poles.
    EditableSurface sphere(sphereDefinition());
    QCOMPARE(sphere.netEdges().size(), std::size_t(8 * 5 + 9 * 4 - 2 * 8));
    EditableSurface cube(cubeDefinition(SubdivisionMode::Limit));
    QCOMPARE(cube.netEdges().size(), std::size_t(12));
    for (const ControlNetEdge& e : cube.netEdges())
        QVERIFY(e.a < e.b);
}

void TestSurfaceEdit::sceneSources()
{
    for (const std::string& name : surfaceDemoNames()) {
        const LoadedScene loaded = loadScene("demo:" + name);
        QCOMPARE(loaded.scene.objects.size(), std::size_t(1));
        QVERIFY2(loaded.trimmable(), loaded.trimUnavailableReason().c_str());
    }
    QTemporaryDir dir;
    const std::string path = (dir.path() + "/two.nurbs.json").toStdString();
    const std::vector<NurbsSurface> surfaces{makeNurbsSphere(glm::dvec3(0.0), 1.0),
                                             makeNurbsTorus(glm::dvec3(3.0, 0.0, 0.0), 1.0, 0.3)};
    saveNurbsJson(path, surfaces);
    const LoadedScene loaded = loadScene(path);
    QCOMPARE(loaded.scene.objects.size(), std::size_t(2));
    QVERIFY(loaded.trimmable());
    QCOMPARE(loaded.scene.objects[0].mesh.triangles, EditableSurface(nurbsDefinition(surfaces[0])).mesh().triangles);
    const std::string broken = (dir.path() + "/broken.nurbs.json").toStdString();
    {
        QFile file(QString::fromStdString(broken));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"format\": \"trimlab-nurbs\", \"version\": 1, \"surfaces\": [");
    }
    QVERIFY_THROWS_EXCEPTION(MeshLoadError, (void)loadScene(broken));
    QVERIFY(isNurbsFileName("a/B.NURBS.JSON"));
    QVERIFY(!isNurbsFileName("mesh.json"));
}

QTEST_GUILESS_MAIN(TestSurfaceEdit)
#include "tst_surface_edit.moc"
