// View ▸ Mesh Statistics in the real main window reports the frame the view shows: after
// File ▸ Replay Stroke Script pushed the top of a unit sphere down through its bottom,
// the dialog gives the shown frame's bounds and volume (what `trimlab info` prints for
// that mesh), not the rest sphere's, and it follows the frame shown while it is open.
#include "design_window.h"
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
#include "core/scene/shape_generators.h"

#include <QtTest>

#include <QAction>
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

QTEST_MAIN(TestMeshStatistics)
#include "tst_mesh_statistics.moc"
