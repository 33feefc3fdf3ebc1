// The designer workflow in the real main window, driven like a user: open a closed mesh,
// turn the brush on (B) and drag on the viewport with QTest, then check the history
// (core/timeline) against what the drag must have done, undo and redo with the
// keyboard, start sets (N) and change rules, render the dynamic rules in the viewport,
// be refused by the homogeneous confluent rule, and save / reopen / fail to open
// projects. Real widgets, a real OpenGL 4.3 context; settings in temporary INI files.
// The drag-update latency on large meshes is measured by bench_design_drag.cpp.
#include "design_window.h"
#include "gl_test_context.h"
#include "message_box_closer.h"

#include "ui/common/document.h"
#include "ui/design/brush_panel.h"
#include "ui/design/brush_tool.h"
#include "ui/design/deformation_timeline_panel.h"
#include "ui/design/deformation_track.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/design/history_exports.h"
#include "ui/window/main_window.h"
#include "ui/design/project_files.h"
#include "core/scene/shape_generators.h"
#include "core/timeline/project_file.h"
#include "ui/viewport/viewport_widget.h"

#include "render/shown_content.h"

#include <QtTest>

#include <QApplication>
#include <QMouseEvent>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QStandardItemModel>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::brushDrag;
using trimlab::test::kWaitMs;
using trimlab::test::MessageBoxCloser;
using trimlab::test::strokeAtCentre;

namespace {

constexpr QSize kViewportSize(256, 192);

bool sameBits(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0;
}

int differingPixels(const QImage& a, const QImage& b)
{
    if (a.size() != b.size())
        return a.width() * a.height();
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    return count;
}

/// Pixels whose blue exceeds their green clearly: the brush tint, never the sphere's
/// front-facing yellow or the background.
int magentaPixels(const QImage& image)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += c.red() > c.green() + 40 && c.blue() > c.green() + 20 ? 1 : 0;
        }
    return count;
}

/// The same drag with Shift held (the brush moves along the grabbed normal: up pulls out,
/// down pushes in), sent as events since QTest's mouse moves carry no modifiers.
void shiftBrushDrag(QWidget* viewport, QPoint from, QPoint to, int steps = 6)
{
    const auto send = [viewport](QEvent::Type type, QPoint at, Qt::MouseButton button, Qt::MouseButtons buttons) {
        QMouseEvent event(type, QPointF(at), viewport->mapToGlobal(QPointF(at)), button, buttons, Qt::ShiftModifier);
        QApplication::sendEvent(viewport, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= steps; ++i)
        send(QEvent::MouseMove, from + (to - from) * i / steps, Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

/// A stroke script that pushes the top cap of the unit sphere down through the bottom, in
/// one homogeneous confluent set: the tip that comes out below and the bottom disk it
/// passes through are trimmed off.
const char* kPushThroughScript = R"({"format": "trimlab-stroke-script", "version": 1, "sets": [
  {"rule": "homogeneous-confluent", "strokes": [
    {"anchor": [0, 1, 0], "drag": [0, -2.4, 0], "radius": 0.8, "strength": 1.0, "profile": "smooth",
     "smoothing": {"iterations": 0, "weights": "uniform", "step": 0.5}}]}]})";

} // namespace

class TestDesignWorkflow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void brushDragDeformsWithinRadius();
    void undoRedoIsBitExact();
    void setsAndRulesAreUndoable();
    void brushRefusesEarlierFrames();
    void strokeInsideAnEarlierDentMovesAPatch();
    void homeFramesWhatIsShown();
    void dynamicRulesRenderInTheViewport();
    void dynamicRulesSetAsideStaticOnlyFeatures();
    void homogeneousConfluentRefusesTrimmedParts();
    void projectRoundTripAndCorruptFile();

private:
    [[nodiscard]] QString path(const QString& name) const { return m_dir.filePath(name); }
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& name)
    {
        return test::showDesignWindow(path(name + QStringLiteral(".ini")), kViewportSize);
    }

    QTemporaryDir m_dir;
    QString m_sphereObj;
};

void TestDesignWorkflow::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
    m_sphereObj = path(QStringLiteral("sphere.obj"));
    QVERIFY(test::writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 3), m_sphereObj)); // 642 vertices
}

// The drag moves only vertices within the brush radius of the grabbed point, records them
// as one frame (exactly the vertices whose bits changed), and the view changes.
void TestDesignWorkflow::brushDragDeformsWithinRadius()
{
    auto window = showWindow(QStringLiteral("drag"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    ViewportWidget* viewport = window->viewport();
    QVERIFY(!window->designWorkspace()->brushAction()->isChecked());
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_B);
    QVERIFY(window->designWorkspace()->brushAction()->isChecked());
    QVERIFY(QSettings(path(QStringLiteral("drag.ini")), QSettings::IniFormat)
                .value(QStringLiteral("brush/toolEnabled"))
                .toBool());
    const double radius = window->designWorkspace()->brushPanel()->settings().radius;
    QVERIFY(std::abs(radius - 0.4 * window->designWorkspace()->session()->baseBounds().radius()) < 1e-3);
    // Hovering tints the region the brush would move (vertex colors toward magenta).
    const QImage untinted = viewport->grabFramebuffer();
    const QPointF centre(kViewportSize.width() / 2.0, kViewportSize.height() / 2.0);
    QMouseEvent hover(QEvent::MouseMove, centre, viewport->mapToGlobal(centre), Qt::NoButton, Qt::NoButton, {});
    QApplication::sendEvent(viewport, &hover);
    QVERIFY(QTest::qWaitFor([&] { return viewport->content()->colorOwner() == render::ContentOwner::BrushRegion; },
                            kWaitMs));
    QVERIFY(QTest::qWaitFor([&] { return magentaPixels(viewport->grabFramebuffer()) > magentaPixels(untinted) + 50; },
                            kWaitMs));
    const QImage before = viewport->grabFramebuffer();
    const DesignSession* session = window->designWorkspace()->session();
    const std::vector<glm::vec3> base = session->timeline().base().positions;

    QVERIFY(strokeAtCentre(*window, QPoint(30, -20)));
    QCOMPARE(session->timeline().frameCount(), 2);
    const timeline::Frame& frame = session->timeline().frame(1);
    QVERIFY(!frame.vertices.empty());
    QVERIFY(frame.stroke.anchorTriangle.has_value());
    QCOMPARE(frame.stroke.brush.radius, radius);
    const std::vector<glm::vec3>& now = session->timeline().currentPositions();
    std::vector<std::uint32_t> changed;
    for (std::uint32_t v = 0; v < now.size(); ++v) {
        if (std::memcmp(&now[v], &base[v], sizeof(glm::vec3)) == 0)
            continue;
        changed.push_back(v);
        // Geodesic distance >= Euclidean: a moved vertex lies within the radius in space too.
        QVERIFY2(glm::distance(glm::dvec3(base[v]), frame.stroke.anchor) < radius + 1e-6,
                 qPrintable(QStringLiteral("vertex %1 moved outside the radius").arg(v)));
    }
    QCOMPARE(changed, frame.vertices);
    QVERIFY(changed.size() < now.size() / 2);
    QVERIFY(window->isWindowModified());
    QVERIFY(window->designWorkspace()->brushTool()->lastUpdateMilliseconds() > 0.0);

    QVERIFY(QTest::qWaitFor([&] { return differingPixels(before, viewport->grabFramebuffer()) > 50; }, kWaitMs));
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(viewport, &leave);
    QCOMPARE(viewport->content()->colorOwner(), render::ContentOwner::None);
}

// Ctrl+Z restores every position bit for bit, Ctrl+Shift+Z re-applies exactly the drag's.
void TestDesignWorkflow::undoRedoIsBitExact()
{
    auto window = showWindow(QStringLiteral("undo"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    const DesignSession* session = window->designWorkspace()->session();
    const std::vector<glm::vec3> base = session->timeline().currentPositions();
    QVERIFY(strokeAtCentre(*window, QPoint(-25, 15)));
    QVERIFY(strokeAtCentre(*window, QPoint(10, 30)));
    const std::vector<glm::vec3> afterFirst = session->timeline().positionsAt(1);
    const std::vector<glm::vec3> afterBoth = session->timeline().currentPositions();
    QVERIFY(!sameBits(afterBoth, base));

    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(session->timeline().frameCount(), 2);
    QVERIFY(sameBits(session->timeline().currentPositions(), afterFirst));
    QVERIFY(sameBits(session->shownPositions(), afterFirst));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(session->timeline().frameCount(), 1);
    QVERIFY(sameBits(session->timeline().currentPositions(), base));
    QVERIFY(!window->isWindowModified()); // back at the clean state

    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(session->timeline().frameCount(), 3);
    QVERIFY(sameBits(session->timeline().currentPositions(), afterBoth));
    QVERIFY(window->isWindowModified());
    int frames = 0;
    QVERIFY(test::waitForNewFrame(*window, frames));
}

// N starts a set (the track marks its reference frame), the rule chooser changes the
// current set's rule, and both undo and redo.
void TestDesignWorkflow::setsAndRulesAreUndoable()
{
    auto window = showWindow(QStringLiteral("sets"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(strokeAtCentre(*window, QPoint(20, 0)));
    DeformationTrack* track = window->designWorkspace()->timelinePanel()->track();
    QCOMPARE(track->referenceFrames(), QList<int>{0});

    window->viewport()->setFocus();
    QTest::keyClick(window->viewport(), Qt::Key_N);
    QCOMPARE(session->timeline().sets().size(), std::size_t(2));
    QCOMPARE(session->timeline().sets()[1].referenceFrame(), 1);
    QCOMPARE(track->referenceFrames(), (QList<int>{0, 1}));

    auto* rule = test::child<QComboBox>(window.get(), "deformationRuleComboBox");
    QVERIFY(rule);
    QCOMPARE(rule->currentData().toString(), QStringLiteral("confluent"));
    rule->setFocus();
    QTest::keyClick(rule, Qt::Key_Down); // confluent → homogeneous confluent
    QCOMPARE(session->timeline().sets()[1].rule, DynamicRule::HomogeneousConfluent);
    QCOMPARE(session->timeline().sets()[0].rule, DynamicRule::Confluent);
    QVERIFY(track->setLabels().at(1).contains(QStringLiteral("omogeneous")));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier); // the rule
    QCOMPARE(session->timeline().sets()[1].rule, DynamicRule::Confluent);
    QCOMPARE(rule->currentData().toString(), QStringLiteral("confluent"));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier); // the set
    QCOMPARE(session->timeline().sets().size(), std::size_t(1));
    QCOMPARE(track->referenceFrames(), QList<int>{0});
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(session->timeline().sets().size(), std::size_t(2));
    QCOMPARE(session->timeline().sets()[1].rule, DynamicRule::HomogeneousConfluent);
    QCOMPARE(track->referenceFrames(), (QList<int>{0, 1}));
}

// Scrubbing back shows the earlier frame exactly; the brush then refuses and says why.
void TestDesignWorkflow::brushRefusesEarlierFrames()
{
    auto window = showWindow(QStringLiteral("scrub"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(strokeAtCentre(*window, QPoint(20, 20)));
    auto* slider = test::child<QSlider>(window.get(), "deformationSlider");
    QVERIFY(slider);
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Home);
    QCOMPARE(session->shownFrame(), 0);
    QVERIFY(sameBits(session->shownPositions(), session->timeline().base().positions));
    int frames = 0;
    QVERIFY(test::waitForNewFrame(*window, frames));
    const QPoint centre(kViewportSize.width() / 2, kViewportSize.height() / 2);
    brushDrag(window->viewport(), centre, centre + QPoint(20, 0));
    QCOMPARE(session->timeline().frameCount(), 2);
    QVERIFY2(window->statusBar()->currentMessage().contains(QStringLiteral("last frame")),
             qPrintable(window->statusBar()->currentMessage()));
    QTest::keyClick(slider, Qt::Key_End);
    QCOMPARE(session->shownFrame(), 1);
}

// A second stroke grabbed at the bottom of a deep dent the first one pushed moves a patch
// like the first, not the few vertices of the stretched walls (spikes).
void TestDesignWorkflow::strokeInsideAnEarlierDentMovesAPatch()
{
    auto window = showWindow(QStringLiteral("dent"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    const DesignSession* session = window->designWorkspace()->session();
    const QPoint centre(kViewportSize.width() / 2, kViewportSize.height() / 2);
    shiftBrushDrag(window->viewport(), centre, centre + QPoint(0, 90)); // a deep dent
    QVERIFY(QTest::qWaitFor([&] { return session->timeline().frameCount() == 2; }, kWaitMs));
    test::waitUntilViewIdle(*window->viewport());
    shiftBrushDrag(window->viewport(), centre, centre + QPoint(0, 30)); // deeper, from its bottom
    QVERIFY(QTest::qWaitFor([&] { return session->timeline().frameCount() == 3; }, kWaitMs));
    const std::size_t first = session->timeline().frame(1).vertices.size();
    const std::size_t second = session->timeline().frame(2).vertices.size();
    qInfo("first stroke %zu vertices, second from inside it %zu", first, second);
    QVERIFY2(second * 2 >= first, qPrintable(QStringLiteral("%1 of %2").arg(second).arg(first)));
}

// Home frames the mesh as shown: the same camera before a stroke and after the stroke was
// undone (it framed every frame the history had held, so a stroke pulled far out and
// undone left Home framing empty space).
void TestDesignWorkflow::homeFramesWhatIsShown()
{
    auto window = showWindow(QStringLiteral("home"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    ViewportWidget* viewport = window->viewport();
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_Home);
    const Camera before = viewport->camera();
    window->designWorkspace()->brushAction()->setChecked(true);
    const QPoint centre(kViewportSize.width() / 2, kViewportSize.height() / 2);
    shiftBrushDrag(viewport, centre, centre - QPoint(0, 90)); // pulled far out along the normal
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(QTest::qWaitFor([&] { return session->timeline().frameCount() == 2; }, kWaitMs));
    window->designWorkspace()->undoAction()->trigger();
    QCOMPARE(session->timeline().frameCount(), 1);
    window->designWorkspace()->brushAction()->setChecked(false);
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_Home);
    const Camera after = viewport->camera();
    QVERIFY2(glm::distance(after.eye, before.eye) < 1e-9 && glm::distance(after.target, before.target) < 1e-9,
             qPrintable(QStringLiteral("eye moved by %1").arg(glm::distance(after.eye, before.eye))));
}

// Two sets under the dynamic rules render through the DynamicTrimRenderer (both levels),
// a drag replaces only the shown level, a GPU reset re-creates everything and shows the
// same frame, a peeling method explains why it cannot run them instead of crashing, and
// resets in a row end in a message, not in a loop.
void TestDesignWorkflow::dynamicRulesRenderInTheViewport()
{
    MessageBoxCloser closer;
    auto window = showWindow(QStringLiteral("dynamic"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(strokeAtCentre(*window, QPoint(25, 0)));
    window->designWorkspace()->newSetAction()->trigger();
    QVERIFY(strokeAtCentre(*window, QPoint(-25, 10)));

    auto* classification = test::child<QComboBox>(window.get(), "classificationComboBox");
    QVERIFY(classification);
    classification->setFocus();
    QTest::keyClick(classification, Qt::Key_Down);
    QVERIFY(window->designWorkspace()->showsDynamicRules());
    ViewportWidget* viewport = window->viewport();
    QVERIFY(QTest::qWaitFor([&] { return viewport->lastDynamicStats().has_value(); }, kWaitMs));
    QVERIFY2(viewport->errorMessage().isEmpty(), qPrintable(viewport->errorMessage()));
    QCOMPARE(viewport->lastDynamicStats()->levels, 2);
    QVERIFY(viewport->lastDynamicStats()->characterizedLevels == 1);

    QVERIFY(strokeAtCentre(*window, QPoint(0, -25))); // picks through meshTriangle, drags the shown level
    QCOMPARE(session->timeline().frameCount(), 4);
    QVERIFY(QTest::qWaitFor(
        [&] { return viewport->lastDynamicStats().has_value() && viewport->errorMessage().isEmpty(); }, kWaitMs));

    // A GPU reset takes the uploaded chain and its cached characterizations with the
    // context: the view uploads and characterizes them again on the new context and shows
    // the same frame (ViewportWidget::recoverFromContextLoss; tst_context_loss.cpp).
    test::waitUntilViewIdle(*viewport); // the drag's last updates may still be on their way
    const QImage beforeReset = viewport->readColorImage();
    const int levels = viewport->lastDynamicStats()->levels;
    const int contexts = viewport->contextsInitialized();
    // Frames are pipelined: the first frame on the new context may be reported together
    // with the next, so the characterization passes are summed over the frames reported.
    int characterizedOnNewContext = 0;
    const QMetaObject::Connection counting = connect(viewport, &ViewportWidget::frameRendered, this, [&] {
        if (viewport->contextsInitialized() == contexts + 1 && viewport->lastDynamicStats())
            characterizedOnNewContext += viewport->lastDynamicStats()->characterizedLevels;
    });
    viewport->recoverFromContextLoss(QStringLiteral("The graphics driver reset the GPU (test)."));
    QVERIFY(QTest::qWaitFor(
        [&] {
            return viewport->contextsInitialized() == contexts + 1 && viewport->lastFrame() &&
                   viewport->lastDynamicStats();
        },
        kWaitMs));
    test::waitUntilViewIdle(*viewport);
    disconnect(counting);
    QCOMPARE(viewport->lastDynamicStats()->levels, levels);
    QCOMPARE(characterizedOnNewContext, levels - 1); // once, then cached
    QVERIFY(viewport->readColorImage() == beforeReset);

    // Peeling cannot run the dynamic rules: it is disabled with the reason, and choosing it
    // anyway (a stored choice) switches to a method that can, saying why, with no dialog.
    auto* method = test::child<QComboBox>(window.get(), "methodComboBox");
    QVERIFY(method);
    const int buffer = method->currentIndex();
    const int peeling = method->findData(QStringLiteral("peeling-f2b"));
    QVERIFY(peeling >= 0);
    const auto* items = qobject_cast<const QStandardItemModel*>(method->model());
    QVERIFY(items && !items->item(peeling)->isEnabled());
    QVERIFY(items->item(buffer)->isEnabled());
    QVERIFY2(
        method->itemData(peeling, Qt::ToolTipRole).toString().contains(QStringLiteral("cannot run the dynamic rules")),
        qPrintable(method->itemData(peeling, Qt::ToolTipRole).toString()));
    method->setCurrentIndex(peeling);
    QVERIFY(items->item(method->currentIndex())->isEnabled());
    QVERIFY2(window->statusBar()->currentMessage().contains(QStringLiteral("cannot run the dynamic rules")),
             qPrintable(window->statusBar()->currentMessage()));
    QVERIFY(
        QTest::qWaitFor([&] { return viewport->errorMessage().isEmpty() && viewport->lastDynamicStats(); }, kWaitMs));
    QVERIFY(closer.seen().isEmpty());
    method->setCurrentIndex(buffer);
    QVERIFY(QTest::qWaitFor([&] { return viewport->errorMessage().isEmpty() && viewport->lastFrame(); }, kWaitMs));

    // Resets in a row: the S-buffer takes over; when it resets in a row too, no leaner
    // method runs the dynamic rules, so rendering stops with a message instead of
    // resetting the GPU every frame, until a method is chosen again.
    const render::FragmentMethodKind chosen = viewport->method();
    const QString reset = QStringLiteral("The graphics driver reset the GPU (test).");
    const int before = viewport->contextsInitialized();
    viewport->recoverFromContextLoss(reset);
    viewport->recoverFromContextLoss(reset);
    QVERIFY(QTest::qWaitFor(
        [&] {
            return viewport->contextsInitialized() == before + 2 && viewport->lastFrame() &&
                   viewport->lastFrame()->stats.method == render::FragmentMethodKind::SBuffer;
        },
        kWaitMs));
    viewport->recoverFromContextLoss(reset);
    viewport->recoverFromContextLoss(reset);
    QVERIFY2(viewport->errorMessage().contains(QStringLiteral("stopped rendering")),
             qPrintable(viewport->errorMessage()));
    QVERIFY(QTest::qWaitFor([&] { return viewport->contextsInitialized() == before + 4; }, kWaitMs));
    QTest::qWait(500);
    QCOMPARE(viewport->contextsInitialized(), before + 4); // no reset loop
    QVERIFY(!viewport->lastFrame());
    viewport->setMethod(chosen);
    QVERIFY(QTest::qWaitFor(
        [&] { return viewport->errorMessage().isEmpty() && viewport->lastFrame() && viewport->lastDynamicStats(); },
        kWaitMs));
    QCOMPARE(viewport->lastFrame()->stats.method, chosen);
    classification->setCurrentIndex(0); // back to the static rule for the next tests' settings
}

// Collision highlighting and capping ticked under the static rule (choices that persist)
// do not stop the dynamic rules: they are disabled with the reason, left out of the frame
// and apply again under the static rule. They gave a modal "The viewport cannot render"
// and a blank view.
void TestDesignWorkflow::dynamicRulesSetAsideStaticOnlyFeatures()
{
    MessageBoxCloser closer;
    auto window = showWindow(QStringLiteral("static-only"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    QVERIFY(strokeAtCentre(*window, QPoint(25, 0)));
    auto* cap = test::child<QCheckBox>(window.get(), "capCheckBox");
    auto* collisions = test::child<QCheckBox>(window.get(), "highlightCollisionsCheckBox");
    auto* reason = test::child<QLabel>(window.get(), "inspectUnavailableLabel");
    QVERIFY(cap && collisions && reason);
    cap->setChecked(true);
    collisions->setChecked(true);
    ViewportWidget* viewport = window->viewport();
    QVERIFY(QTest::qWaitFor(
        [&] { return viewport->lastFrame() && viewport->lastFrame()->settings.highlight.collisions; }, kWaitMs));

    auto* classification = test::child<QComboBox>(window.get(), "classificationComboBox");
    classification->setCurrentIndex(1);
    QVERIFY(window->designWorkspace()->showsDynamicRules());
    QVERIFY(
        QTest::qWaitFor([&] { return viewport->lastDynamicStats().has_value() && viewport->lastFrame(); }, kWaitMs));
    QTest::qWait(200); // a refused frame would open its dialog from the event loop
    QVERIFY2(closer.seen().isEmpty(), qPrintable(closer.seen().join(QLatin1Char('|'))));
    QVERIFY2(viewport->errorMessage().isEmpty(), qPrintable(viewport->errorMessage()));
    QVERIFY(!viewport->lastFrame()->settings.highlight.collisions);
    QVERIFY(!viewport->lastFrame()->settings.cap.enabled);
    QVERIFY(cap->isChecked() && !cap->isEnabled());
    QVERIFY(collisions->isChecked() && !collisions->isEnabled());
    QVERIFY(reason->isVisibleTo(window.get()));
    QVERIFY(reason->text().contains(QStringLiteral("static rule")));

    classification->setCurrentIndex(0);
    QVERIFY(QTest::qWaitFor(
        [&] { return viewport->lastFrame() && viewport->lastFrame()->settings.highlight.collisions; }, kWaitMs));
    QVERIFY(cap->isEnabled() && collisions->isEnabled());
    QVERIFY(!reason->isVisibleTo(window.get()));
    collisions->setChecked(false);
    cap->setChecked(false);
}

// After a replayed stroke pushed the top cap through the bottom under the homogeneous
// confluent rule, a press whose region reaches the trimmed-off tip is refused with the
// reason in the status bar; a press far from it is not.
void TestDesignWorkflow::homogeneousConfluentRefusesTrimmedParts()
{
    auto window = showWindow(QStringLiteral("homogeneous"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    const QString script = path(QStringLiteral("push-through.json"));
    std::ofstream(script.toStdString()) << kPushThroughScript;
    QSignalSpy replayed(window->designWorkspace()->historyExports(), &HistoryExports::replayed);
    window->designWorkspace()->historyExports()->replay(script);
    QVERIFY(replayed.wait(kWaitMs));
    const DesignSession* session = window->designWorkspace()->session();
    QCOMPARE(session->timeline().frameCount(), 2);
    QCOMPARE(session->timeline().sets().front().rule, DynamicRule::HomogeneousConfluent);
    QVERIFY(session->undoStack()->isClean() && session->undoStack()->count() == 0);
    window->designWorkspace()->brushAction()->setChecked(true);

    // From below: the hole the cap punched through the bottom, ringed by the surface.
    ViewportWidget* viewport = window->viewport();
    viewport->setCamera(Camera{{0.0, -4.0, 0.05}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 45.0});
    int frames = 0;
    QVERIFY(test::waitForNewFrame(*window, frames));
    const QPoint centre(kViewportSize.width() / 2, kViewportSize.height() / 2);
    std::optional<QPoint> rim;
    for (int dx = 0; dx < kViewportSize.width() / 2 && !rim; ++dx) {
        const auto pixel = viewport->trimPixelAt(QPointF(centre + QPoint(dx, 0)) + QPointF(0.5, 0.5));
        if (pixel && pixel->covered())
            rim = centre + QPoint(dx, 0);
    }
    QVERIFY2(rim.has_value(), "nothing visible to grab from below");
    brushDrag(viewport, *rim, *rim + QPoint(0, 20));
    QCOMPARE(session->timeline().frameCount(), 2);
    QVERIFY2(window->statusBar()->currentMessage().contains(QStringLiteral("Homogeneous confluent rule")),
             qPrintable(window->statusBar()->currentMessage()));
    QVERIFY(window->designWorkspace()->lastTrimCheckMilliseconds() > 0.0);
    qInfo("homogeneous confluent check: %.1f ms (first press: chain and BVHs built)",
          window->designWorkspace()->lastTrimCheckMilliseconds());

    // From the side with a small radius, far from the cap: allowed.
    auto* radius = test::child<QDoubleSpinBox>(window.get(), "brushRadiusSpinBox");
    radius->setValue(0.2);
    viewport->setCamera(Camera{{4.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 45.0});
    QVERIFY(test::waitForNewFrame(*window, frames));
    QVERIFY(strokeAtCentre(*window, QPoint(15, 0)));
    qInfo("second check (cached chain): %.1f ms", window->designWorkspace()->lastTrimCheckMilliseconds());
}

// Save → reopen gives the same history (Timeline ==); a damaged project is reported
// and the session shown stays as it was; unsaved changes are saved when the prompt is
// confirmed.
void TestDesignWorkflow::projectRoundTripAndCorruptFile()
{
    MessageBoxCloser closer;
    auto window = showWindow(QStringLiteral("project"));
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    window->designWorkspace()->brushAction()->setChecked(true);
    QVERIFY(strokeAtCentre(*window, QPoint(20, -10)));
    window->designWorkspace()->newSetAction()->trigger();
    QVERIFY(strokeAtCentre(*window, QPoint(-20, 10)));
    QVERIFY(window->windowTitle().contains(QStringLiteral("[*]")) && window->isWindowModified());

    const QString project = path(QStringLiteral("design.trimlab"));
    QString error;
    QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(project, &error), qPrintable(error));
    QVERIFY(!window->isWindowModified());
    QVERIFY(window->windowTitle().startsWith(QStringLiteral("design.trimlab")));
    const timeline::Timeline saved = window->designWorkspace()->session()->timeline();
    QVERIFY(timeline::readProject(project.toStdString()).timeline == saved);

    QVERIFY(test::openDesignAndWait(*window, m_sphereObj)); // clean: no prompt
    QCOMPARE(window->designWorkspace()->session()->timeline().frameCount(), 1);
    QVERIFY(test::openDesignAndWait(*window, project));
    QVERIFY(window->designWorkspace()->session()->timeline() == saved);
    QCOMPARE(window->document()->filePath(), QFileInfo(project).absoluteFilePath());
    QVERIFY(window->recentFiles().contains(QFileInfo(project).absoluteFilePath()));

    // A damaged copy: the dialog names the file, nothing else changes.
    std::string bytes;
    {
        std::ifstream in(project.toStdString(), std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const QString damaged = path(QStringLiteral("damaged.trimlab"));
    std::ofstream(damaged.toStdString(), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    QSignalSpy failed(window.get(), &MainWindow::sceneLoadFailed);
    window->openSource(damaged);
    QVERIFY(failed.wait(kWaitMs));
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, kWaitMs));
    QVERIFY2(closer.seen().last().contains(QStringLiteral("damaged.trimlab")), qPrintable(closer.seen().last()));
    QVERIFY(window->designWorkspace()->session()->timeline() == saved);
    QCOMPARE(window->document()->filePath(), QFileInfo(project).absoluteFilePath());

    // Unsaved changes: the prompt's default (Save) writes them before the mesh opens.
    QVERIFY(strokeAtCentre(*window, QPoint(0, 20)));
    const timeline::Timeline edited = window->designWorkspace()->session()->timeline();
    QVERIFY(test::openDesignAndWait(*window, m_sphereObj));
    QVERIFY(timeline::readProject(project.toStdString()).timeline == edited);
}

QTEST_MAIN(TestDesignWorkflow)
#include "tst_design_workflow.moc"
