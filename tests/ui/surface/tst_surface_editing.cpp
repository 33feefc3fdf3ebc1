// The editable-surface UI in the real main window (thesis 8.2), driven like a user:
// Create ▸ NURBS ▸ Sphere through its menu action, the control net over the view, a
// click, a Shift+click and a drag on projected control points with QTest (one timeline
// frame, undo and redo bit for bit), the brush on control points, the Surface panel's
// subdivision level (the expected triangle count) and "Show control net", and a broken
// cage file reported with its file and line. Real widgets, a real OpenGL 4.3 context;
// settings in temporary INI files.
#include "design_window.h"
#include "gl_test_context.h"
#include "message_box_closer.h"

#include "ui/design/brush_panel.h"
#include "ui/design/brush_tool.h"
#include "ui/design/deformation_timeline_panel.h"
#include "ui/design/project_files.h"
#include "ui/design/control_net_overlay.h"
#include "ui/design/control_point_tool.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/window/main_window.h"
#include "ui/surface/surface_workspace.h"
#include "ui/surface/surface_panel.h"
#include "ui/viewport/viewport_widget.h"

#include "render/shown_content.h"

#include "core/catalog/fig8_13_history.h"
#include "core/catalog/scene_source.h"
#include "core/catalog/surface_scenes.h"
#include "core/design/control_brush.h"
#include "core/timeline/project_file.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QStatusBar>
#include <QSpinBox>
#include <QFileInfo>
#include <QMenu>
#include <QDockWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstring>
#include <fstream>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::kWaitMs;

namespace {

constexpr QSize kViewportSize(256, 192);

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

/// Pixels that differ clearly from the top-left corner's (the background there).
int coveredPixels(const QImage& image)
{
    const QColor background = image.pixelColor(0, 0);
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - background.red()) + std::abs(c.green() - background.green()) +
                                 std::abs(c.blue() - background.blue()) >
                             60
                         ? 1
                         : 0;
        }
    return count;
}

/// A control point whose projection lies inside the view, at least `margin` pixels from
/// every other point's (seam twins and poles project onto one spot) and that a click on
/// its rounded position picks, nearest to `aim` first; nullopt when there is none.
std::optional<std::uint32_t> isolatedPoint(const std::vector<std::optional<QPointF>>& points, QPointF aim,
                                           const std::vector<std::uint32_t>& exclude, double margin = 12.0)
{
    std::optional<std::uint32_t> best;
    double bestDistance = 1e300;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        if (!points[i] || std::find(exclude.begin(), exclude.end(), i) != exclude.end())
            continue;
        const QPointF p = *points[i];
        if (p.x() < margin || p.y() < margin || p.x() > kViewportSize.width() - margin ||
            p.y() > kViewportSize.height() - margin)
            continue;
        bool alone = true;
        for (std::uint32_t j = 0; j < points.size() && alone; ++j)
            alone = j == i || !points[j] || QLineF(p, *points[j]).length() >= margin;
        const double distance = QLineF(p, aim).length();
        if (alone && distance < bestDistance) {
            best = i;
            bestDistance = distance;
        }
    }
    return best;
}

/// Clicks the isolated control point nearest to the view's centre; returns it.
std::optional<std::uint32_t> clickCentralPoint(ViewportWidget* viewport, const ControlNetOverlay& overlay)
{
    const std::vector<std::optional<QPointF>> points = overlay.projectedPoints();
    const std::optional<std::uint32_t> point =
        isolatedPoint(points, QPointF(kViewportSize.width() / 2.0, kViewportSize.height() / 2.0), {});
    if (point)
        QTest::mouseClick(viewport, Qt::LeftButton, {}, points[*point]->toPoint());
    return point;
}

/// The unit average of `a`'s moves (after − before), or (0,0,0).
glm::dvec3 moveDirection(const timeline::Frame& frame)
{
    glm::dvec3 sum(0.0);
    for (const timeline::ControlPointMove& move : frame.controlMoves)
        sum += move.after - move.before;
    const double length = glm::length(sum);
    return length > 0.0 ? sum / length : sum;
}

} // namespace

class TestSurfaceEditing : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void createNurbsSphereThroughTheMenu();
    void everyCreateActionStartsASurfaceSession();
    void surfaceDemoOpensAsSurfaceSession();
    void historyDemosOpenWithTheirHistory();
    void fitFramesTheControlNet();
    void boxSelectsControlPoints();
    void pickShiftPickDragUndoRedo();
    void brushMovesControlPoints();
    void brushOutOfReachSaysSo();
    void subdivisionLevelAndShowNet();
    void brokenCageFileNamesFileAndLine();
    void alongNormalEditsAndDynamicRules();
    void rebuildWithEditsAsksAndProjectRoundTrip();
    void homogeneousConfluentRefusesTrimmedControlEdits();
    void editedNurbsSavesAndReopensFromItsFile();

private:
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& name);
    /// Triggers the Create menu action `objectName` and waits for the surface's frame.
    [[nodiscard]] static bool create(MainWindow& window, const char* objectName);

    QTemporaryDir m_dir;
};

void TestSurfaceEditing::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

std::unique_ptr<MainWindow> TestSurfaceEditing::showWindow(const QString& name)
{
    auto window = test::showDesignWindow(m_dir.filePath(name + QStringLiteral(".ini")), kViewportSize);
    // The first start opens the default demo; let it arrive so it cannot replace the surface.
    if (!QTest::qWaitFor([&] { return window->scene() && !window->isLoading(); }, kWaitMs))
        qWarning("the default scene did not load");
    return window;
}

bool TestSurfaceEditing::create(MainWindow& window, const char* objectName)
{
    auto* action = window.findChild<QAction*>(QString::fromLatin1(objectName));
    if (!action) {
        qWarning("no action %s", objectName);
        return false;
    }
    action->trigger();
    const DesignSession* session = window.designWorkspace()->session();
    if (!session || !session->surface()) {
        qWarning("%s: no surface session (%s)", objectName, qPrintable(window.statusBar()->currentMessage()));
        return false;
    }
    int frames = 0;
    return test::waitForNewFrame(window, frames) && window.viewport()->lastFrame().has_value();
}

// The action builds a 9 × 5 NURBS sphere session; the view shows it (trimmed frame
// covers pixels) and the overlay draws every control point of the definition.
void TestSurfaceEditing::createNurbsSphereThroughTheMenu()
{
    auto window = showWindow(QStringLiteral("create"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(session->timeline().hasSurface());
    QCOMPARE(session->timeline().surface()->kind(), SurfaceKind::Nurbs);
    QCOMPARE(session->timeline().frameCount(), 1);
    QCOMPARE(session->timeline().surface()->controlPointCount(), std::size_t(9 * 5));
    ControlNetOverlay* overlay = window->designWorkspace()->controlNetOverlay();
    QCOMPARE(overlay->pointCount(), session->timeline().surface()->controlPointCount());
    QVERIFY(overlay->edgeCount() > 0);
    QVERIFY(overlay->isVisible());
    QVERIFY(window->surfaceWorkspace()->controlPointsAction()->isChecked());
    QVERIFY(!window->designWorkspace()->brushAction()->isChecked());
    // The sphere's tessellation is what the viewport renders, trimmed.
    const ViewportFrame& frame = *window->viewport()->lastFrame();
    QCOMPARE(frame.scene->objects.at(0).mesh.triangles.size(), session->timeline().base().triangles.size());
    QVERIFY(frame.settings.trimEnabled);
    const int covered = coveredPixels(window->viewport()->grabFramebuffer());
    qInfo("sphere covers %d of %d pixels", covered, kViewportSize.width() * kViewportSize.height());
    QVERIFY2(covered > kViewportSize.width() * kViewportSize.height() / 10, qPrintable(QString::number(covered)));
    QVERIFY(window->surfaceWorkspace()->panel()->kind() == SurfacePanel::Kind::Nurbs);
}

// Every entry of the Create menu (but From Cage File…) starts a surface session whose
// net has the definition's control points; the open patch is shown without trimming.
void TestSurfaceEditing::everyCreateActionStartsASurfaceSession()
{
    auto window = showWindow(QStringLiteral("every"));
    const char* names[] = {"createNurbsSphereAction",
                           "createNurbsTorusAction",
                           "createNurbsTubeAction",
                           "createNurbsPatchAction",
                           "createSubdivision_cubeAction",
                           "createSubdivision_torusAction",
                           "createSubdivision_t-shapeAction",
                           "createSubdivision_tetrahedronAction",
                           "createSubdivision_octahedronAction"};
    for (const char* name : names) {
        QVERIFY2(create(*window, name), name);
        const DesignSession* session = window->designWorkspace()->session();
        QCOMPARE(window->designWorkspace()->controlNetOverlay()->pointCount(),
                 session->timeline().surface()->controlPointCount());
        QVERIFY(!session->timeline().base().triangles.empty());
        const bool patch = std::strcmp(name, "createNurbsPatchAction") == 0;
        QCOMPARE(window->viewport()->lastFrame()->settings.trimEnabled, !patch);
        QCOMPARE(window->surfaceWorkspace()->panel()->kind() == SurfacePanel::Kind::NurbsPatch, patch);
    }
}

// File ▸ Open Demo ▸ nurbs-sphere is edited through its control points too.
void TestSurfaceEditing::surfaceDemoOpensAsSurfaceSession()
{
    auto window = showWindow(QStringLiteral("demo"));
    QVERIFY(test::openDesignAndWait(*window, QStringLiteral("demo:nurbs-sphere")));
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(session->surface());
    QCOMPARE(window->designWorkspace()->controlNetOverlay()->pointCount(), std::size_t(9 * 5));
    QVERIFY(test::openDesignAndWait(*window, QStringLiteral("demo:pushed-sphere"))); // a mesh demo
    QVERIFY(!window->designWorkspace()->session()->surface());
    QVERIFY(!window->designWorkspace()->controlNetOverlay()->isVisible());
}

// File ▸ Open Demo lists every built-in demo, and the demos that carry a control-point
// history open with it (they opened as a plain mesh: "No editable surface", Frame 0 / 0).
void TestSurfaceEditing::historyDemosOpenWithTheirHistory()
{
    auto window = showWindow(QStringLiteral("history-demo"));
    auto* menu = window->findChild<QMenu*>(QStringLiteral("openDemoMenu"));
    QVERIFY(menu);
    QStringList listed;
    for (const QAction* action : menu->actions())
        listed << action->text();
    for (const DemoEntry& demo : builtInDemos())
        QVERIFY2(listed.contains(QString::fromStdString(demo.source).mid(int(kDemoPrefix.size()))),
                 demo.source.c_str());
    for (const char* name : {"subdivision-push", "nurbs-fig8-13"}) {
        const QString source = QStringLiteral("demo:") + QLatin1String(name);
        QAction* item = nullptr;
        for (QAction* action : menu->actions())
            item = action->text() == QLatin1String(name) ? action : item;
        QVERIFY2(item, name);
        item->trigger();
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         return window->scene() && window->scene()->source == source.toStdString() &&
                                window->viewport()->lastFrame().has_value();
                     },
                     kWaitMs),
                 name);
        const DesignSession* session = window->designWorkspace()->session();
        QVERIFY2(session && session->surface(), name);
        const std::optional<timeline::Timeline> expected = surfaceDemoHistory(name);
        QCOMPARE(session->timeline().frameCount(), expected->frameCount());
        QVERIFY(session->timeline().frameCount() > 1);
        QCOMPARE(session->shownFrame(), expected->frameCount() - 1);
        QCOMPARE(session->timeline().sets().size(), expected->sets().size());
        QVERIFY(window->surfaceWorkspace()->panel()->kind() != SurfacePanel::Kind::None);
        QCOMPARE(window->designWorkspace()->controlNetOverlay()->pointCount(),
                 expected->surface()->controlPointCount());
        QVERIFY(window->designWorkspace()->timelineDock()->isVisible());
    }
}

// F frames the control net with the surface: every point of the subdivision cube's cage
// is in the view afterwards (the cage's corners reach well past the limit surface, and
// Fit framed the surface alone).
void TestSurfaceEditing::fitFramesTheControlNet()
{
    auto window = showWindow(QStringLiteral("fit-net"));
    QVERIFY(create(*window, "createSubdivision_cubeAction"));
    ViewportWidget* viewport = window->viewport();
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_F);
    const std::vector<std::optional<QPointF>> points =
        window->designWorkspace()->controlNetOverlay()->projectedPoints();
    QVERIFY(!points.empty());
    const QRectF view(QPointF(0.0, 0.0), QSizeF(viewport->size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        QVERIFY2(points[i] && view.contains(*points[i]),
                 qPrintable(QStringLiteral("control point %1 is out of view").arg(i)));
}

// Ctrl + drag from empty space draws a box: the points inside it join the selection, the
// others stay out, the camera keeps still, and no frame is recorded.
void TestSurfaceEditing::boxSelectsControlPoints()
{
    auto window = showWindow(QStringLiteral("box"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    ViewportWidget* viewport = window->viewport();
    ControlNetOverlay* overlay = window->designWorkspace()->controlNetOverlay();
    ControlPointTool* tool = window->designWorkspace()->controlPointTool();
    const std::vector<std::optional<QPointF>> points = overlay->projectedPoints();
    const QPoint from(4, 4); // a corner: no point there
    const QPoint to(kViewportSize.width() / 2, kViewportSize.height() / 2);
    std::vector<std::uint32_t> expected;
    const QRectF box = QRectF(from, to).normalized();
    for (std::uint32_t i = 0; i < points.size(); ++i)
        if (points[i] && box.contains(*points[i]))
            expected.push_back(i);
    QVERIFY(!expected.empty() && expected.size() < points.size());
    const Camera before = viewport->camera();
    const int frames = window->designWorkspace()->session()->timeline().frameCount();
    QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, from);
    QTest::mouseMove(viewport, (from + to) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, to);
    QCOMPARE(tool->selection(), expected);
    QCOMPARE(overlay->selection(), expected);
    QVERIFY(glm::distance(viewport->camera().eye, before.eye) < 1e-12);
    QCOMPARE(window->designWorkspace()->session()->timeline().frameCount(), frames);
}

// Click picks one point, Shift+click adds a second, a drag from the first moves both:
// one frame whose moved vertices lie in the supports; undo and redo are bit-exact.
void TestSurfaceEditing::pickShiftPickDragUndoRedo()
{
    auto window = showWindow(QStringLiteral("drag"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    DesignSession* session = window->designWorkspace()->session();
    ControlPointTool* tool = window->designWorkspace()->controlPointTool();
    ControlNetOverlay* overlay = window->designWorkspace()->controlNetOverlay();
    ViewportWidget* viewport = window->viewport();
    const std::vector<glm::vec3> base = session->timeline().currentPositions();
    const std::vector<glm::dvec3> baseControl = session->timeline().currentControlPoints();

    const std::vector<std::optional<QPointF>> points = overlay->projectedPoints();
    const QPointF centre(kViewportSize.width() / 2.0, kViewportSize.height() / 2.0);
    const std::optional<std::uint32_t> first = isolatedPoint(points, centre, {});
    QVERIFY(first);
    const std::optional<std::uint32_t> second = isolatedPoint(points, centre, {*first});
    QVERIFY(second);
    const QPoint firstAt = points[*first]->toPoint();
    const QPoint secondAt = points[*second]->toPoint();

    QTest::mouseClick(viewport, Qt::LeftButton, {}, firstAt);
    QCOMPARE(tool->selection(), std::vector<std::uint32_t>{*first});
    QCOMPARE(overlay->selection(), tool->selection());
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, secondAt);
    std::vector<std::uint32_t> both{*first, *second};
    std::sort(both.begin(), both.end());
    QCOMPARE(tool->selection(), both);
    QCOMPARE(session->timeline().frameCount(), 1); // clicks record nothing

    QTest::mousePress(viewport, Qt::LeftButton, {}, firstAt);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(viewport, firstAt + QPoint(4 * i, -3 * i));
    QVERIFY(tool->isDragging());
    QVERIFY(tool->lastUpdateMilliseconds() > 0.0);
    qInfo("drag update (evaluate the moved supports, hand the pose over): %.3f ms", tool->lastUpdateMilliseconds());
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, firstAt + QPoint(20, -15));
    QCOMPARE(session->timeline().frameCount(), 2);
    QCOMPARE(session->undoStack()->count(), 1);
    const timeline::Frame& frame = session->timeline().frame(1);
    QVERIFY(frame.isControlEdit());
    QVERIFY(!frame.vertices.empty());
    std::vector<std::uint32_t> movedPoints;
    for (const timeline::ControlPointMove& move : frame.controlMoves)
        movedPoints.push_back(move.index);
    for (std::uint32_t picked : both)
        QVERIFY(std::binary_search(movedPoints.begin(), movedPoints.end(), picked));
    // Every moved vertex depends on a moved control point, and exactly the listed ones changed.
    std::vector<std::uint32_t> supports;
    for (std::uint32_t c : movedPoints) {
        const std::vector<std::uint32_t> s = session->surface()->support(c);
        supports.insert(supports.end(), s.begin(), s.end());
    }
    std::sort(supports.begin(), supports.end());
    for (std::uint32_t v : frame.vertices)
        QVERIFY2(std::binary_search(supports.begin(), supports.end(), v), qPrintable(QString::number(v)));
    const std::vector<glm::vec3> edited = session->timeline().currentPositions();
    std::vector<std::uint32_t> changed;
    for (std::uint32_t v = 0; v < edited.size(); ++v)
        if (std::memcmp(&edited[v], &base[v], sizeof(glm::vec3)) != 0)
            changed.push_back(v);
    QCOMPARE(changed, frame.vertices);
    // The grabbed point followed the cursor in the view plane: its projection moved by the drag.
    const std::optional<QPointF> movedTo = overlay->projectedPoints()[*first];
    QVERIFY(movedTo);
    QVERIFY2(QLineF(*movedTo, QPointF(firstAt + QPoint(20, -15))).length() < 1.5,
             qPrintable(QStringLiteral("point %1 from (%2, %3) to (%4, %5)")
                            .arg(*first)
                            .arg(points[*first]->x())
                            .arg(points[*first]->y())
                            .arg(movedTo->x())
                            .arg(movedTo->y())));
    const std::vector<glm::dvec3> editedControl = session->timeline().currentControlPoints();

    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(session->timeline().frameCount(), 1);
    QVERIFY(sameBits(session->timeline().currentPositions(), base));
    QVERIFY(sameBits(session->shownPositions(), base));
    QVERIFY(sameBits(session->timeline().currentControlPoints(), baseControl));
    QVERIFY(sameBits(session->surface()->controlPoints(), baseControl));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(session->timeline().frameCount(), 2);
    QVERIFY(sameBits(session->timeline().currentPositions(), edited));
    QVERIFY(sameBits(session->timeline().currentControlPoints(), editedControl));
    QVERIFY(sameBits(session->surface()->controlPoints(), editedControl));
    int frames = 0;
    QVERIFY(test::waitForNewFrame(*window, frames));

    // A click on empty space clears the selection.
    QTest::mouseClick(viewport, Qt::LeftButton, {}, QPoint(2, 2));
    QVERIFY(tool->selection().empty());
}

// The brush (B) on a surface session moves control points within its radius of the
// grabbed surface point, as one control edit.
void TestSurfaceEditing::brushMovesControlPoints()
{
    auto window = showWindow(QStringLiteral("brush"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    DesignSession* session = window->designWorkspace()->session();
    window->designWorkspace()->brushAction()->setChecked(true);
    QVERIFY(!window->surfaceWorkspace()->controlPointsAction()->isChecked());
    const double radius = window->designWorkspace()->brushPanel()->settings().radius;
    const QPoint centre(kViewportSize.width() / 2, kViewportSize.height() / 2);
    QTest::mousePress(window->viewport(), Qt::LeftButton, {}, centre);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(window->viewport(), centre + QPoint(5 * i, 0));
    QTest::mouseRelease(window->viewport(), Qt::LeftButton, {}, centre + QPoint(25, 0));
    QCOMPARE(session->timeline().frameCount(), 2);
    const timeline::Frame& frame = session->timeline().frame(1);
    QVERIFY(frame.isControlEdit());
    QVERIFY(!frame.vertices.empty());
    // The press grabbed the sphere where the view's central ray meets it: about the unit
    // vector towards the eye (the view is framed on the sphere's centre, the origin; the
    // tessellation lies within 0.02 of the sphere, the centre pixel within half a pixel).
    const Camera camera = window->viewport()->camera();
    QVERIFY(glm::length(camera.target) < 0.01);
    const glm::dvec3 anchor = glm::normalize(camera.eye - camera.target);
    for (const timeline::ControlPointMove& move : frame.controlMoves)
        QVERIFY2(glm::distance(move.before, anchor) < radius + 0.05,
                 qPrintable(QStringLiteral("control point %1 is %2 from the anchor, radius %3")
                                .arg(move.index)
                                .arg(glm::distance(move.before, anchor))
                                .arg(radius)));
    QVERIFY(frame.controlMoves.size() < session->surface()->controlPointCount());
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(session->timeline().frameCount(), 1);
}

// A brush too small to reach any control point records nothing and says why (the
// nearest point's distance and the radius), instead of silently doing nothing.
void TestSurfaceEditing::brushOutOfReachSaysSo()
{
    auto window = showWindow(QStringLiteral("brush-reach"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    DesignSession* session = window->designWorkspace()->session();
    BrushPanel* panel = window->designWorkspace()->brushPanel();
    auto* radiusBox = panel->findChild<QDoubleSpinBox*>(QStringLiteral("brushRadiusSpinBox"));
    QVERIFY(radiusBox);
    radiusBox->setValue(radiusBox->minimum()); // as the user's edit: the brush takes it
    const double radius = panel->settings().radius;
    QCOMPARE(window->designWorkspace()->brushTool()->settings().radius, radius);
    // The press lands near the unit vector towards the eye (brushMovesControlPoints); no
    // control point of the sphere lies within the radius of it.
    const Camera camera = window->viewport()->camera();
    const glm::dvec3 anchor = glm::normalize(camera.eye - camera.target);
    QVERIFY(nearestControlPointDistance(session->surface()->controlPoints(), anchor) > radius + 0.05);
    window->designWorkspace()->brushAction()->setChecked(true);
    const QPoint centre(kViewportSize.width() / 2, kViewportSize.height() / 2);
    QTest::mousePress(window->viewport(), Qt::LeftButton, {}, centre);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(window->viewport(), centre + QPoint(5 * i, 0));
    QTest::mouseRelease(window->viewport(), Qt::LeftButton, {}, centre + QPoint(25, 0));
    QCOMPARE(session->timeline().frameCount(), 1);
    const QString message = window->statusBar()->currentMessage();
    QVERIFY2(message.contains(QStringLiteral("reached no control point")), qPrintable(message));
    QVERIFY2(message.contains(QString::number(radius, 'g', 3)), qPrintable(message));
}

// A fresh subdivision cube: level 2 → 6·4² quads = 192 triangles, level 1 → 48; the
// show-net checkbox hides and shows the overlay and is remembered.
void TestSurfaceEditing::subdivisionLevelAndShowNet()
{
    auto window = showWindow(QStringLiteral("subdivision"));
    QVERIFY(create(*window, "createSubdivision_cubeAction"));
    QCOMPARE(window->designWorkspace()->session()->timeline().surface()->kind(), SurfaceKind::Subdivision);
    QCOMPARE(window->designWorkspace()->controlNetOverlay()->pointCount(), std::size_t(8));
    QCOMPARE(window->designWorkspace()->controlNetOverlay()->edgeCount(), std::size_t(12));
    QVERIFY(window->surfaceWorkspace()->panel()->kind() == SurfacePanel::Kind::Subdivision);
    auto* level = test::child<QSpinBox>(window.get(), "surfaceLevelSpinBox");
    QVERIFY(level && level->isEnabled());
    for (const auto& [wanted, triangles] : {std::pair{2, 192}, std::pair{1, 48}, std::pair{0, 12}}) {
        level->setValue(wanted);
        const DesignSession* session = window->designWorkspace()->session();
        QVERIFY(session && session->surface());
        QCOMPARE(session->timeline().base().triangles.size(), std::size_t(triangles));
        QCOMPARE(window->viewport()->scene()->objects.at(0).mesh.triangles.size(), std::size_t(triangles));
        QCOMPARE(session->timeline().surface()->subdivision().settings.level, wanted);
    }
    auto* showNet = test::child<QCheckBox>(window.get(), "showControlNetCheckBox");
    QVERIFY(showNet && showNet->isChecked());
    ControlNetOverlay* overlay = window->designWorkspace()->controlNetOverlay();
    QVERIFY(overlay->isVisible());
    showNet->click();
    QVERIFY(!overlay->isVisible());
    QVERIFY(!QSettings(m_dir.filePath(QStringLiteral("subdivision.ini")), QSettings::IniFormat)
                 .value(QStringLiteral("surface/showNet"))
                 .toBool());
    showNet->click();
    QVERIFY(overlay->isVisible());
}

// A cage file with an out-of-range face index is refused with "FILE:LINE:" and the
// surface shown stays.
void TestSurfaceEditing::brokenCageFileNamesFileAndLine()
{
    test::MessageBoxCloser closer;
    auto window = showWindow(QStringLiteral("cage"));
    QVERIFY(create(*window, "createSubdivision_cubeAction"));
    const QString path = m_dir.filePath(QStringLiteral("broken-cage.obj"));
    std::ofstream(path.toStdString()) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n";
    QSignalSpy failed(window.get(), &MainWindow::sceneLoadFailed);
    QVERIFY(!window->surfaceWorkspace()->createFromCageFile(path));
    QCOMPARE(failed.count(), 1);
    const QString message = failed.at(0).at(1).toString();
    QVERIFY2(message.contains(QStringLiteral("broken-cage.obj:5")), qPrintable(message));
    QVERIFY(window->designWorkspace()->session());
    QCOMPARE(window->designWorkspace()->session()->timeline().surface()->kind(), SurfaceKind::Subdivision);
}

// Ctrl+drag moves the selection along its normal (outward on the sphere when the cursor
// goes up), the panel's "Move along normal" does the same by its distance; a new set
// with the homogeneous confluent rule takes the next edit, and the dynamic rules render.
void TestSurfaceEditing::alongNormalEditsAndDynamicRules()
{
    auto window = showWindow(QStringLiteral("normal"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    DesignSession* session = window->designWorkspace()->session();
    ViewportWidget* viewport = window->viewport();
    const std::optional<std::uint32_t> point =
        clickCentralPoint(viewport, *window->designWorkspace()->controlNetOverlay());
    QVERIFY(point);
    const glm::dvec3 start = session->timeline().currentControlPoints()[*point];
    const glm::dvec3 normal = session->surface()->controlPointNormal(*point);
    QVERIFY(glm::length(normal) > 0.5);
    const QPoint at = window->designWorkspace()->controlNetOverlay()->projectedPoints()[*point]->toPoint();
    QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, at);
    for (int i = 1; i <= 4; ++i)
        QTest::mouseMove(viewport, at + QPoint(0, -5 * i));
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, at + QPoint(0, -20));
    QCOMPARE(session->timeline().frameCount(), 2);
    const glm::dvec3 moved = session->timeline().currentControlPoints()[*point] - start;
    QVERIFY2(glm::dot(glm::normalize(moved), normal) > 0.999, "a Ctrl drag up must pull out along the normal");

    auto* step = test::child<QDoubleSpinBox>(window.get(), "surfaceNormalStepSpinBox");
    auto* button = test::child<QPushButton>(window.get(), "surfaceMoveAlongNormalButton");
    QVERIFY(step && button && button->isEnabled());
    step->setValue(-0.1);
    const glm::dvec3 normalNow = session->surface()->controlPointNormal(*point);
    const glm::dvec3 before = session->timeline().currentControlPoints()[*point];
    button->click();
    QCOMPARE(session->timeline().frameCount(), 3);
    const glm::dvec3 pushed = session->timeline().currentControlPoints()[*point] - before;
    QVERIFY(std::abs(glm::length(pushed) - 0.1) < 1e-9);
    QVERIFY(glm::dot(moveDirection(session->timeline().frame(2)), normalNow) < -0.999);

    window->designWorkspace()->newSetAction()->trigger();
    auto* rule = test::child<QComboBox>(window.get(), "deformationRuleComboBox");
    QCOMPARE(rule->currentData().toString(), QStringLiteral("confluent"));
    rule->setFocus();
    QTest::keyClick(rule, Qt::Key_Down); // a user's choice (activated): confluent → homogeneous confluent
    QCOMPARE(session->timeline().sets().size(), std::size_t(2));
    button->click();
    QCOMPARE(session->timeline().frameCount(), 4);
    QCOMPARE(session->timeline().setOfFrame(3), 1);
    QCOMPARE(session->timeline().sets()[1].rule, DynamicRule::HomogeneousConfluent);

    auto* classification = test::child<QComboBox>(window.get(), "classificationComboBox");
    classification->setCurrentIndex(1); // dynamic rules
    QVERIFY(window->designWorkspace()->showsDynamicRules());
    QVERIFY(QTest::qWaitFor([&] { return viewport->lastDynamicStats().has_value(); }, kWaitMs));
    QCOMPARE(viewport->lastDynamicStats()->levels, 2);
    QVERIFY2(viewport->errorMessage().isEmpty(), qPrintable(viewport->errorMessage()));
    // A drag under the dynamic rules previews through the shown level and records a frame.
    // (The new set's rule is confluent again: the homogeneous one may refuse this part.)
    window->designWorkspace()->startNewSet(DynamicRule::Confluent);
    const std::optional<std::uint32_t> again =
        clickCentralPoint(viewport, *window->designWorkspace()->controlNetOverlay());
    QVERIFY(again);
    const QPoint from = window->designWorkspace()->controlNetOverlay()->projectedPoints()[*again]->toPoint();
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    for (int i = 1; i <= 3; ++i)
        QTest::mouseMove(viewport, from + QPoint(-5 * i, 0));
    QVERIFY(viewport->content()->chain() != nullptr);
    QCOMPARE(viewport->content()->chainOwner(), render::ContentOwner::DesignHistory);
    QCOMPARE(viewport->content()->poseOwner(), render::ContentOwner::DesignHistory); // the preview
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, from + QPoint(-15, 0));
    QCOMPARE(session->timeline().frameCount(), 5);
    QCOMPARE(session->timeline().setOfFrame(4), 2);
    int frames = 0;
    QVERIFY(test::waitForNewFrame(*window, frames));
    QVERIFY(viewport->lastDynamicStats().has_value());
    QCOMPARE(viewport->lastDynamicStats()->levels, 3);
    QVERIFY2(viewport->errorMessage().isEmpty(), qPrintable(viewport->errorMessage()));
    classification->setCurrentIndex(0);
}

// A level change on a history with edits asks first (Cancel keeps everything); a saved
// surface project opens again as a surface session with its net and history.
void TestSurfaceEditing::rebuildWithEditsAsksAndProjectRoundTrip()
{
    test::MessageBoxCloser closer; // presses the default button: Cancel
    auto window = showWindow(QStringLiteral("project"));
    QVERIFY(create(*window, "createSubdivision_cubeAction"));
    DesignSession* session = window->designWorkspace()->session();
    QVERIFY(clickCentralPoint(window->viewport(), *window->designWorkspace()->controlNetOverlay()));
    test::child<QPushButton>(window.get(), "surfaceMoveAlongNormalButton")->click();
    QCOMPARE(session->timeline().frameCount(), 2);
    auto* level = test::child<QSpinBox>(window.get(), "surfaceLevelSpinBox");
    const int before = level->value();
    level->setValue(before == 1 ? 2 : 1);
    QCOMPARE(closer.seen().size(), 1);
    QVERIFY(closer.seen().front().contains(QStringLiteral("new history")));
    QCOMPARE(window->designWorkspace()->session(), session); // canceled: the same history
    QCOMPARE(session->timeline().frameCount(), 2);
    QCOMPARE(level->value(), before); // the panel shows the surface's level again

    const QString project = m_dir.filePath(QStringLiteral("cube.trimlab"));
    QString error;
    QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(project, &error), qPrintable(error));
    const timeline::Timeline saved = session->timeline();
    QVERIFY(test::openDesignAndWait(*window, project));
    const DesignSession* reopened = window->designWorkspace()->session();
    QVERIFY(reopened->timeline() == saved);
    QVERIFY(reopened->surface());
    QCOMPARE(window->designWorkspace()->controlNetOverlay()->pointCount(), std::size_t(8));
    QVERIFY(sameBits(reopened->surface()->controlPoints(), saved.currentControlPoints()));
    QVERIFY(window->surfaceWorkspace()->panel()->kind() == SurfacePanel::Kind::Subdivision);
}

// The Fig. 8.13 history with its second set under the homogeneous confluent rule: the
// north pole was pushed down through the sphere and its tip out below is trimmed off, so
// moving the pole's points again is refused (with the reason), in a new confluent set
// it is not.
void TestSurfaceEditing::homogeneousConfluentRefusesTrimmedControlEdits()
{
    const QString project = m_dir.filePath(QStringLiteral("fig8-13.trimlab"));
    timeline::saveProject(fig8_13NurbsHistory(DynamicRule::Confluent, DynamicRule::HomogeneousConfluent),
                          project.toStdString());
    auto window = showWindow(QStringLiteral("homogeneous"));
    QVERIFY(test::openDesignAndWait(*window, project));
    DesignSession* session = window->designWorkspace()->session();
    QVERIFY(session->surface());
    QCOMPARE(session->timeline().frameCount(), 5);
    const NurbsSurface& sphere = session->timeline().surface()->nurbs().surface;
    const auto northPole = std::uint32_t(sphere.index(0, sphere.countV - 1));
    const auto minusX = std::uint32_t(sphere.index(4, 2)); // φ = 180°, on the equator
    auto* step = test::child<QDoubleSpinBox>(window.get(), "surfaceNormalStepSpinBox");
    auto* button = test::child<QPushButton>(window.get(), "surfaceMoveAlongNormalButton");
    step->setValue(0.1);
    ControlPointTool* tool = window->designWorkspace()->controlPointTool();

    tool->setSelection({northPole});
    button->click();
    QCOMPARE(session->timeline().frameCount(), 5);
    QVERIFY2(window->statusBar()->currentMessage().contains(QStringLiteral("Homogeneous confluent rule")),
             qPrintable(window->statusBar()->currentMessage()));
    QVERIFY(sameBits(session->surface()->controlPoints(), session->timeline().currentControlPoints()));

    // The −x point of the equator pulls the whole half sphere around −x (the rational
    // circle's supports are long), the dent's trimmed-off vertices included: refused too.
    tool->setSelection({minusX});
    button->click();
    QCOMPARE(session->timeline().frameCount(), 5);

    // A new set under the confluent rule may deform them.
    window->designWorkspace()->startNewSet(DynamicRule::Confluent);
    tool->setSelection({northPole});
    button->click();
    QVERIFY2(session->timeline().frameCount() == 6, qPrintable(window->statusBar()->currentMessage()));
    QCOMPARE(session->timeline().setOfFrame(5), 2);
    QVERIFY(session->timeline().frame(5).controlMoves.size() > 1); // the pole's tied points
}

// Create ▸ NURBS ▸ Save NURBS Surface As… writes the edited control points; From NURBS
// File… starts a new session whose surface has exactly them (the file stores doubles
// with round-trip precision). Without a NURBS session there is nothing to save.
void TestSurfaceEditing::editedNurbsSavesAndReopensFromItsFile()
{
    auto window = showWindow(QStringLiteral("nurbsfile"));
    QVERIFY(create(*window, "createNurbsSphereAction"));
    DesignSession* session = window->designWorkspace()->session();
    auto* saveAction = window->findChild<QAction*>(QStringLiteral("saveNurbsAction"));
    QVERIFY(saveAction && saveAction->isEnabled());
    auto* step = test::child<QDoubleSpinBox>(window.get(), "surfaceNormalStepSpinBox");
    auto* button = test::child<QPushButton>(window.get(), "surfaceMoveAlongNormalButton");
    QVERIFY(clickCentralPoint(window->viewport(), *window->designWorkspace()->controlNetOverlay()));
    step->setValue(0.2);
    button->click();
    QCOMPARE(session->timeline().frameCount(), 2);
    const std::vector<glm::dvec3> edited = session->timeline().currentControlPoints();
    QVERIFY(edited != session->timeline().surface()->controlPoints());

    const QString path = m_dir.filePath(QStringLiteral("edited.nurbs.json"));
    QVERIFY(window->surfaceWorkspace()->saveNurbsSurface(path));
    session->undoStack()->setClean(); // the reopen must not stop at "save changes?"
    QVERIFY(window->surfaceWorkspace()->createFromNurbsFile(path));
    const DesignSession* reopened = window->designWorkspace()->session();
    QVERIFY(reopened != nullptr && reopened->surface() != nullptr);
    QCOMPARE(reopened->timeline().frameCount(), 1);
    QVERIFY(reopened->timeline().currentControlPoints() == edited);

    QVERIFY(create(*window, "createSubdivision_cubeAction"));
    QVERIFY(!saveAction->isEnabled());
    QVERIFY(!window->surfaceWorkspace()->saveNurbsSurface(m_dir.filePath(QStringLiteral("cube.nurbs.json"))));
    QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("cube.nurbs.json"))));
}

QTEST_MAIN(TestSurfaceEditing)
#include "tst_surface_editing.moc"
