// View ▸ Mesh Statistics in the real main window reports the frame the view shows: after
// File ▸ Replay Stroke Script pushed the top of a unit sphere down through its bottom,
// the dialog gives the shown frame's bounds and volume (what `trimlab info` prints for
// that mesh), not the rest sphere's, and it follows the frame shown while it is open.
// Measure gives the trimmed solid's volume, area and section in the clipping plane, and
// each object's self-intersections, as the core measures the frame shown, or why the
// view shows no solid.
#include "design_window.h"
#include "inspect_window.h"
#include "gl_test_context.h"
#include "message_box_closer.h"
#include "named_child.h"

#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/design/history_exports.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/window/main_window.h"
#include "ui/window/scene_statistics.h"

#include "render/shown_content.h"

#include "core/mesh/mesh_validation.h"
#include "core/trim/csg_expression.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/inspect_workspace.h"
#include "core/scene/shape_generators.h"

#include <QtTest>

#include <QAction>
#include <QCheckBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTextEdit>

#include <fstream>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::kWaitMs;

namespace {

constexpr QSize kViewportSize(256, 192);

/// Pushes the top cap of the unit sphere down through the bottom, in one set.
const char* kPushThroughScript = R"({"format": "trimlab-stroke-script", "version": 1, "sets": [
  {"rule": "confluent", "strokes": [
    {"anchor": [0, 1, 0], "drag": [0, -2.4, 0], "radius": 0.8, "strength": 1.0, "profile": "smooth",
     "smoothing": {"iterations": 0, "weights": "uniform", "step": 0.5}}]}]})";

/// The dialog's text once View ▸ Mesh Statistics was chosen.
QString statisticsText(MainWindow& window)
{
    test::child<QAction>(&window, "meshStatisticsAction")->trigger();
    auto* text = window.findChild<QTextEdit*>(QStringLiteral("sceneStatisticsText"));
    return text ? text->toPlainText() : QString();
}

} // namespace

class TestMeshStatistics : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void reportsTheFrameShown();
    void measuresTheTrimmedSolidShown();

private:
    QTemporaryDir m_dir;
    QString m_sphere;
};

void TestMeshStatistics::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
    m_sphere = m_dir.filePath(QStringLiteral("sphere.obj"));
    QVERIFY(test::writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 3), m_sphere));
}

void TestMeshStatistics::reportsTheFrameShown()
{
    test::MessageBoxCloser closer;
    auto window = test::showDesignWindow(m_dir.filePath(QStringLiteral("statistics.ini")), kViewportSize);
    QVERIFY(test::openDesignAndWait(*window, m_sphere));
    const QString script = m_dir.filePath(QStringLiteral("push-through.json"));
    std::ofstream(script.toStdString()) << kPushThroughScript;
    QSignalSpy replayed(window->designWorkspace()->historyExports(), &HistoryExports::replayed);
    window->designWorkspace()->historyExports()->replay(script);
    QVERIFY(replayed.wait(kWaitMs));
    const DesignSession* session = window->designWorkspace()->session();
    QVERIFY(session && session->timeline().frameCount() == 2 && session->shownFrame() == 1);
    QVERIFY(QTest::qWaitFor([&] { return window->viewport()->lastFrame().has_value(); }, kWaitMs));

    const std::string name = window->scene()->scene.objects.front().name;
    const MeshValidationReport& rest = window->scene()->reports.front();
    TriangleMesh shownMesh = session->timeline().base();
    shownMesh.positions = session->shownPositions();
    const MeshValidationReport shown = validateMesh(shownMesh);
    qInfo("rest: volume %.3f, y from %.3f; frame shown: volume %.3f, y from %.3f", rest.signedVolume, rest.bounds.min.y,
          shown.signedVolume, shown.bounds.min.y);
    QVERIFY(shown.bounds.min.y < rest.bounds.min.y - 0.2); // the cap came out below
    QVERIFY(shown.signedVolume < 0.8 * rest.signedVolume);
    QVERIFY(window->viewport()->content()->posedScene()->objects.front().mesh.positions == shownMesh.positions);

    const QString text = statisticsText(*window);
    const QString shownReport = QString::fromStdString(formatReport(shown, name));
    const QString restReport = QString::fromStdString(formatReport(rest, name));
    QVERIFY2(text.contains(shownReport), qPrintable(text));
    QVERIFY2(!text.contains(restReport), qPrintable(text));

    // Open, it follows the frame shown: the rest sphere at frame 0, the pushed one again at 1.
    auto* dialog = window->findChild<SceneStatisticsDialog*>();
    QVERIFY(dialog && dialog->isVisible());
    window->designWorkspace()->showFrame(0);
    QVERIFY2(QTest::qWaitFor([&] { return dialog->text().contains(restReport); }, kWaitMs), qPrintable(dialog->text()));
    window->designWorkspace()->showFrame(1);
    QVERIFY2(QTest::qWaitFor([&] { return dialog->text().contains(shownReport); }, kWaitMs),
             qPrintable(dialog->text()));
    dialog->close();
}

// The csg-trio's (0 | 1) - 2 cut by the first clipping plane: Measure runs off the UI
// thread and reports the exact solid of the frame shown (its volume is the export's), the
// plane's section, and how often each object crosses itself (the pushed sphere does, the
// ball and the ring do not). With trimming off there
// is no solid, and the reason is given; the crossings are still counted.
void TestMeshStatistics::measuresTheTrimmedSolidShown()
{
    auto window =
        test::showInspectWindow(m_dir.filePath(QStringLiteral("measure.ini")), QStringLiteral("demo:csg-trio"));
    InspectScene* scene = window->inspectWorkspace()->scene();
    CsgSettings csg = scene->csg();
    csg.expression = parseCsgExpression("(0 | 1) - 2", nullptr).value();
    scene->editCsg(csg, QStringLiteral("test CSG"));
    QVERIFY(test::waitForFrame(*window, [&](const ViewportFrame& f) { return f.settings.csg == csg; }));
    QTest::mouseClick(test::revealed(test::child<QCheckBox>(window.get(), "clipPlaneEnabled0")), Qt::LeftButton);
    QVERIFY(test::waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.clipSet().anyEnabled(); }));
    const ViewportFrame frame = *window->viewport()->lastFrame();

    (void)statisticsText(*window);
    auto* dialog = window->findChild<SceneStatisticsDialog*>();
    QVERIFY(dialog && dialog->isVisible());
    QSignalSpy measured(dialog, &SceneStatisticsDialog::measured);
    QTest::mouseClick(test::child<QPushButton>(dialog, "measureSolidButton"), Qt::LeftButton);
    QVERIFY(dialog->isMeasuring() || !measured.isEmpty());
    QVERIFY(measured.count() == 1 || measured.wait(60000));

    const SolidMeasures expected = measureTrimmedSolid(*frame.scene, frame.settings);
    QVERIFY(std::abs(expected.volume - trimmedSolid(*frame.scene, frame.settings).stats.signedVolume) <= 0.0);
    QCOMPARE(expected.sections.size(), std::size_t(1));
    QVERIFY(expected.volume > 0.0 && expected.sections.front().area > 0.0);
    const QString text = dialog->measuresText();
    qInfo("%s", qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("volume %1,").arg(expected.volume, 0, 'g', 6)), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("surface area %1 ").arg(expected.area, 0, 'g', 6)), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("cross-section in clipping plane 1: area %1")
                               .arg(expected.sections.front().area, 0, 'g', 6)),
             qPrintable(text));
    QVERIFY2(
        text.contains(QStringLiteral("the CSG %1").arg(QString::fromStdString(formatCsgExpression(csg.expression)))),
        qPrintable(text));
    int crossingObjects = 0;
    for (const SceneObject& object : frame.scene->objects) {
        const SelfIntersections crossings = selfIntersections(object.mesh);
        crossingObjects += crossings.pairs > 0 ? 1 : 0;
        const QString crossingText = crossings.pairs == 0
                                         ? QStringLiteral("does not cross itself")
                                         : QStringLiteral("%1 triangle pairs cross (%2 triangles involved)")
                                               .arg(crossings.pairs)
                                               .arg(crossings.triangles);
        QVERIFY2(
            text.contains(
                QStringLiteral("Self-intersections of %1: %2").arg(QString::fromStdString(object.name), crossingText)),
            qPrintable(text));
    }
    QCOMPARE(crossingObjects, 1); // the pushed sphere

    QTest::keyClick(test::revealed(test::child<QCheckBox>(window.get(), "trimCheckBox")), Qt::Key_Space);
    QVERIFY(test::waitForFrame(*window, [](const ViewportFrame& f) { return !f.settings.trimEnabled; }));
    QTest::mouseClick(test::child<QPushButton>(dialog, "measureSolidButton"), Qt::LeftButton);
    QVERIFY(measured.count() == 2 || measured.wait(60000));
    QVERIFY2(dialog->measuresText().startsWith(QStringLiteral("No trimmed solid to measure: Trimming is off")),
             qPrintable(dialog->measuresText()));
    QVERIFY(dialog->measuresText().contains(QStringLiteral("Self-intersections of")));
    dialog->close();
}

QTEST_MAIN(TestMeshStatistics)
#include "tst_mesh_statistics.moc"
