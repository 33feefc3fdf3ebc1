// The real main window driven like a user: open files through openSource() (the path
// every menu, drop and the command line take), change the panel with keyboard and mouse,
// and check the framebuffer and the renderer's per-pixel answers against the exact CPU
// reference. Settings go to INI files in a temporary folder, never the user's.
#include "demo_window.h"
#include "gl_test_context.h"
#include "image_artifacts.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "shown_main_window.h"
#include "widget_test_main.h"
#include "plain_obj.h"
#include "test_paths.h"
#include "trim_comparison.h"

#include "ui/render_panel/clip_plane_editor.h"
#include "ui/viewport/orientation_axes.h"
#include "ui/window/main_window.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/render_panel/render_panel.h"
#include "core/catalog/demo_scenes.h"
#include "ui/common/scene_loader.h"
#include "core/trim/reference_renderer.h"
#include "ui/viewport/viewport_widget.h"

#include <QtTest>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTextEdit>
#include <QThreadPool>
#include <QToolBar>
#include <QToolButton>

#include <cstdio>
#include <fstream>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;
using trimlab::test::MessageBoxCloser;

namespace {

constexpr QSize kViewportSize(256, 192);
constexpr int kWaitMs = 20000;

void writeText(const QString& path, const char* text)
{
    std::ofstream(path.toStdString()) << text;
}

/// A tetrahedron without its bottom face: an open surface (three boundary edges).
const char* kOpenTetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
/// Line 3 references vertex 7 of 2.
const char* kBrokenObj = "v 0 0 0\nv 1 0 0\nf 1 2 7\n";

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void firstStartShowsTrimmedDemo();
    void ruleChangeRerendersAndMatchesReference();
    void loadErrorKeepsPreviousScene();
    void openSurfaceDisablesTrimControls();
    void settingsRoundTrip();
    void thresholdRulePersists();
    void recentFilesAndDrop();
    void exportWritesTheViewportImage();
    void cancelDiscardsTheLoad();
    void slowLoadShowsProgressAndCancelDiscards();
    void mouseAndKeysMoveTheCamera();
    void aboutNamesTheOpenGLRenderer();
    void iconsAreDrawn();
    void viewPresetsAndHelp();

private:
    [[nodiscard]] QString path(const QString& name) const { return m_dir.filePath(name); }
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& settingsName,
                                                         QSize viewportSize = kViewportSize);
    [[nodiscard]] bool waitForScene(MainWindow& window, const QString& source);
    [[nodiscard]] static bool waitForFrame(MainWindow& window);

    QTemporaryDir m_dir;
    QString m_pushedSphereObj;
};

void TestMainWindow::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
    m_pushedSphereObj = path(QStringLiteral("pushed-sphere.obj"));
    QVERIFY(test::writePlainObj(makeDemoScene("pushed-sphere")->objects.front().mesh, m_pushedSphereObj));
}

std::unique_ptr<MainWindow> TestMainWindow::showWindow(const QString& settingsName, QSize viewportSize)
{
    return test::showMainWindow(path(settingsName + QStringLiteral(".ini")), viewportSize);
}

bool TestMainWindow::waitForScene(MainWindow& window, const QString& source)
{
    return QTest::qWaitFor(
        [&] { return !window.isLoading() && window.scene() && window.scene()->source == source.toStdString(); },
        kWaitMs);
}

bool TestMainWindow::waitForFrame(MainWindow& window)
{
    return QTest::qWaitFor([&] { return window.viewport()->lastFrame().has_value(); }, kWaitMs);
}

// A new user sees the whole pushed sphere trimmed by the alternating border rule: the
// tunnel the finger left is open, and no clipping plane cuts the scene (it confused
// first-time users; Plane 1 is prepared, off). The screenshots in docs/ come from
// tst_window_layout.cpp.
void TestMainWindow::firstStartShowsTrimmedDemo()
{
    auto window = showWindow(QStringLiteral("first-start"), QSize());
    window->resize(1180, 760);
    QVERIFY(waitForScene(*window, MainWindow::defaultSource()));
    QVERIFY(waitForFrame(*window));
    QVERIFY(window->viewport()->errorMessage().isEmpty());
    QVERIFY(window->windowTitle().contains(QStringLiteral("pushed-sphere")));
    const ViewportFrame frame = *window->viewport()->lastFrame();
    QVERIFY(frame.settings.trimEnabled);
    QCOMPARE(frame.settings.rule, StaticRule::AlternatingBorder);
    QVERIFY(!frame.settings.clipSet().anyEnabled());
    QCOMPARE(frame.settings.clip.normal, glm::dvec3(0.0, 0.0, -1.0));
    const auto failure = test::lastFrameDisagreement(*window, QStringLiteral("first-start"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    QVERIFY(window->findChild<QLabel*>(QStringLiteral("frameTimeLabel"))->text().contains(QStringLiteral("ms")));
    QTest::qWait(100); // let the status bar settle
    const QString shot = QString::fromStdString((test::outputDir() / "main-window.png").string());
    QVERIFY(window->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));
}

// Changing the rule with the keyboard re-renders, changes the framebuffer, and the new
// trim image agrees with the CPU reference for the viewport's exact camera and size.
void TestMainWindow::ruleChangeRerendersAndMatchesReference()
{
    auto window = showWindow(QStringLiteral("rule-change"));
    window->openSource(m_pushedSphereObj);
    QVERIFY(waitForScene(*window, m_pushedSphereObj));
    QVERIFY(waitForFrame(*window));
    QCOMPARE(window->viewport()->lastFrame()->pixelSize, kViewportSize);
    const QImage before = window->viewport()->grabFramebuffer();

    auto* rule = child<QComboBox>(window.get(), "ruleComboBox");
    QVERIFY(rule);
    QTest::keyClick(rule, Qt::Key_Home); // alternating border → parity
    QCOMPARE(rule->currentData().toString(), QStringLiteral("parity"));
    QVERIFY(QTest::qWaitFor(
        [&] {
            const auto& frame = window->viewport()->lastFrame();
            return frame && frame->settings.rule == StaticRule::Parity;
        },
        kWaitMs));
    const QImage after = window->viewport()->grabFramebuffer();
    QCOMPARE(after.size(), before.size());
    int changed = 0;
    for (int y = 0; y < after.height(); ++y)
        for (int x = 0; x < after.width(); ++x)
            changed += after.pixel(x, y) != before.pixel(x, y) ? 1 : 0;
    QVERIFY2(changed > 100, qPrintable(QStringLiteral("only %1 pixels changed").arg(changed)));
    const TrimImage actual = window->viewport()->readTrimImage(); // first: lastFrame() is then its frame

    const ViewportFrame frame = *window->viewport()->lastFrame();
    const ReferenceRenderer reference(window->scene()->scene);
    const ReferenceResult expected =
        reference.render(frame.camera, frame.pixelSize.width(), frame.pixelSize.height(), frame.settings);
    const test::TrimComparison comparison = test::compareTrimImages(actual, expected.trim, expected.diagnostics);
    qInfo("%s", qPrintable(comparison.summary()));
    if (comparison.agreement() < 0.999 || comparison.excludedFraction() > 0.05) {
        const QString artifacts =
            test::writeComparisonArtifacts(QStringLiteral("rule-change"), test::trimImageToPicture(actual),
                                           test::trimImageToPicture(expected.trim), comparison.disagreementMask);
        QFAIL(qPrintable(comparison.summary() + QStringLiteral("; ") + artifacts));
    }
    QVERIFY(comparison.coveredPixels > kViewportSize.width() * kViewportSize.height() / 10);
}

void TestMainWindow::loadErrorKeepsPreviousScene()
{
    auto window = showWindow(QStringLiteral("load-error"));
    const QString good = QStringLiteral("demo:sphere");
    window->openSource(good);
    QVERIFY(waitForScene(*window, good));
    QVERIFY(waitForFrame(*window));
    const QString title = window->windowTitle();

    const QString broken = path(QStringLiteral("broken.obj"));
    writeText(broken, kBrokenObj);
    MessageBoxCloser closer;
    QSignalSpy failed(window.get(), &MainWindow::sceneLoadFailed);
    window->openSource(broken);
    QVERIFY(failed.wait(kWaitMs));
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, kWaitMs));
    const QString shown = closer.seen().front();
    QVERIFY2(shown.contains(QStringLiteral("broken.obj")), qPrintable(shown));
    QVERIFY2(shown.contains(QStringLiteral(":3")), qPrintable(shown)); // the offending line
    QCOMPARE(failed.front().at(0).toString(), broken);
    QCOMPARE(QString::fromStdString(window->scene()->source), good);
    QCOMPARE(window->windowTitle(), title);
    QVERIFY(window->viewport()->lastFrame().has_value());
    QVERIFY(!window->recentFiles().contains(broken));
}

void TestMainWindow::openSurfaceDisablesTrimControls()
{
    auto window = showWindow(QStringLiteral("open-surface"));
    const QString open = path(QStringLiteral("open-tetrahedron.obj"));
    writeText(open, kOpenTetrahedron);
    window->openSource(open);
    QVERIFY(waitForScene(*window, open));
    QVERIFY(waitForFrame(*window));
    QVERIFY(!window->scene()->trimmable());
    auto* trim = child<QCheckBox>(window.get(), "trimCheckBox");
    auto* rule = child<QComboBox>(window.get(), "ruleComboBox");
    auto* reason = child<QLabel>(window.get(), "trimUnavailableLabel");
    QVERIFY(trim && rule && reason);
    QVERIFY(!trim->isEnabled());
    QVERIFY(!rule->isEnabled());
    QVERIFY(trim->isChecked()); // the user's choice is kept for the next scene
    QVERIFY(reason->isVisible());
    QVERIFY2(reason->text().contains(QString::fromStdString(window->scene()->trimUnavailableReason())),
             qPrintable(reason->text()));
    QVERIFY(!window->viewport()->lastFrame()->settings.trimEnabled);
    QVERIFY(window->viewport()->readTrimImage().pixels.size() > 0);

    // A closed surface brings the controls back.
    window->openSource(m_pushedSphereObj);
    QVERIFY(waitForScene(*window, m_pushedSphereObj));
    QVERIFY(trim->isEnabled() && rule->isEnabled());
    QVERIFY(!reason->isVisible());
    QVERIFY(QTest::qWaitFor(
        [&] {
            const auto& frame = window->viewport()->lastFrame();
            return frame && frame->settings.trimEnabled;
        },
        kWaitMs));
}

// Rule, k, trim and clip plane edited with keyboard and mouse persist into a new window.
void TestMainWindow::settingsRoundTrip()
{
    const QString settings = QStringLiteral("round-trip");
    {
        auto window = showWindow(settings);
        QTest::keyClick(child<QComboBox>(window.get(), "ruleComboBox"), Qt::Key_Up); // → positive index
        auto* k = child<QSpinBox>(window.get(), "kSpinBox");
        QTest::keyClick(k, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(k, QStringLiteral("24"));
        QTest::keyClick(k, Qt::Key_Return);
        QCOMPARE(k->value(), 24);
        QTest::mouseClick(child<QCheckBox>(window.get(), "clipPlaneEnabled0"), Qt::LeftButton);
        QTest::mouseClick(child<QToolButton>(window.get(), "clipPreset+X"), Qt::LeftButton);
        auto* offset = child<QDoubleSpinBox>(window.get(), "clipOffsetSpin");
        QTest::keyClick(offset, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(offset, QStringLiteral("0.25"));
        QTest::keyClick(offset, Qt::Key_Return);
        QTest::keyClick(child<QCheckBox>(window.get(), "trimCheckBox"), Qt::Key_Space);
        QVERIFY(!window->viewport()->trimSettings().trimEnabled);
        QCOMPARE(window->viewport()->k(), 24);
        window->close();
    }
    auto window = showWindow(settings);
    const RenderChoices restored = window->renderWorkspace()->panel()->renderChoices();
    QCOMPARE(restored.trim.rule, StaticRule::PositiveIndex);
    QCOMPARE(restored.k, 24);
    QVERIFY(!restored.trim.trimEnabled);
    QVERIFY(restored.trim.clip.enabled);
    QCOMPARE(restored.trim.clip.normal, glm::dvec3(1.0, 0.0, 0.0));
    QCOMPARE(restored.trim.clip.offset, 0.25);
    QCOMPARE(window->viewport()->k(), 24);
    QCOMPARE(window->viewport()->trimSettings().clip.offset, 0.25);
}

// The threshold rules: choosing "|w| ≥ K" with the keyboard enables the K spin box; on
// the crossing loop (w = 2 where the tube passes through itself) the viewport renders
// |w| >= 2 in agreement with the CPU reference, and the rule with its K persists into a
// new window.
void TestMainWindow::thresholdRulePersists()
{
    const QString settings = QStringLiteral("threshold-rule");
    {
        auto window = showWindow(settings);
        window->openSource(QStringLiteral("demo:crossing-loop"));
        QVERIFY(waitForScene(*window, QStringLiteral("demo:crossing-loop")));
        QVERIFY(waitForFrame(*window));
        auto* rule = child<QComboBox>(window.get(), "ruleComboBox");
        auto* threshold = child<QSpinBox>(window.get(), "ruleThresholdSpinBox");
        QVERIFY(rule && threshold);
        QVERIFY(!threshold->isEnabled());
        QTest::keyClick(rule, Qt::Key_End);
        QCOMPARE(rule->currentData().toString(), QStringLiteral("|w|>="));
        QVERIFY(threshold->isEnabled());
        QTest::keyClick(threshold, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(threshold, QStringLiteral("2"));
        QTest::keyClick(threshold, Qt::Key_Return);
        QVERIFY(QTest::qWaitFor(
            [&] {
                const auto& frame = window->viewport()->lastFrame();
                return frame && frame->settings.rule == StaticRule::absAtLeast(2);
            },
            kWaitMs));
        const TrimImage actual = window->viewport()->readTrimImage(); // first: lastFrame() is then its frame
        const ViewportFrame frame = *window->viewport()->lastFrame();
        const ReferenceResult expected =
            ReferenceRenderer(window->scene()->scene)
                .render(frame.camera, frame.pixelSize.width(), frame.pixelSize.height(), frame.settings);
        const test::TrimComparison comparison = test::compareTrimImages(actual, expected.trim, expected.diagnostics);
        qInfo("%s", qPrintable(comparison.summary()));
        QVERIFY2(comparison.agreement() >= 0.999, qPrintable(comparison.summary()));
        // The loop's crossing (w = 2) is the only interior: some pixels, far from all.
        QVERIFY(comparison.coveredPixels > 0);
        window->close();
    }
    auto window = showWindow(settings);
    QCOMPARE(window->renderWorkspace()->panel()->renderChoices().trim.rule, StaticRule::absAtLeast(2));
    QCOMPARE(child<QSpinBox>(window.get(), "ruleThresholdSpinBox")->value(), 2);
}

// Opened files enter Open Recent; a dropped file opens; a recent file that vanished is
// removed with a message.
void TestMainWindow::recentFilesAndDrop()
{
    auto window = showWindow(QStringLiteral("recent"));
    const QString doomed = path(QStringLiteral("doomed.obj"));
    QVERIFY(QFile::copy(m_pushedSphereObj, doomed));
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(doomed)});
    // As a drag from a file manager: enter (which makes the window the drop target), drop.
    QDragEnterEvent enter(QPoint(20, 20), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window.get(), &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(20.0, 20.0), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(window.get(), &drop);
    QVERIFY(drop.isAccepted());
    QVERIFY(waitForScene(*window, doomed));
    QCOMPARE(window->recentFiles().value(0), doomed);

    QVERIFY(QFile::remove(doomed));
    QAction* entry = nullptr;
    for (QAction* menu : window->menuBar()->actions())
        for (QAction* item : menu->menu()->actions())
            if (item->menu() && item->text().contains(QStringLiteral("Recent")))
                for (QAction* recent : item->menu()->actions())
                    entry = recent->text() == doomed ? recent : entry;
    QVERIFY(entry);
    MessageBoxCloser closer;
    entry->trigger();
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, kWaitMs));
    QVERIFY(closer.seen().front().contains(QStringLiteral("doomed.obj")));
    QVERIFY(!window->recentFiles().contains(doomed));
    QCOMPARE(QString::fromStdString(window->scene()->source), doomed); // the scene stays
}

void TestMainWindow::exportWritesTheViewportImage()
{
    auto window = showWindow(QStringLiteral("export"));
    QVERIFY(waitForScene(*window, MainWindow::defaultSource()));
    QVERIFY(waitForFrame(*window));
    const QString png = path(QStringLiteral("export.png"));
    QString error;
    QVERIFY2(window->exportImage(png, &error), qPrintable(error));
    const QImage saved(png);
    QCOMPARE(saved.size(), kViewportSize);
    const QImage color = window->viewport()->readColorImage().convertToFormat(QImage::Format_RGB32);
    QCOMPARE(saved.convertToFormat(QImage::Format_RGB32), color);
    QVERIFY(!window->exportImage(path(QStringLiteral("missing-folder/export.png")), &error));
    QVERIFY(!error.isEmpty());
}

void TestMainWindow::cancelDiscardsTheLoad()
{
    auto window = showWindow(QStringLiteral("cancel"));
    QVERIFY(waitForScene(*window, MainWindow::defaultSource()));
    QSignalSpy loaded(window.get(), &MainWindow::sceneLoaded);
    QSignalSpy canceled(window->sceneLoader(), &SceneLoader::canceled);
    window->openSource(QStringLiteral("demo:nested-spheres"));
    QVERIFY(window->isLoading());
    window->sceneLoader()->cancel();
    QCOMPARE(canceled.count(), 1);
    QVERIFY(!window->isLoading());
    QVERIFY(QThreadPool::globalInstance()->waitForDone(kWaitMs)); // the worker finishes...
    QTest::qWait(50);
    QCOMPARE(loaded.count(), 0); // ...and its result is dropped
    QCOMPARE(QString::fromStdString(window->scene()->source), MainWindow::defaultSource());
}

// A load that takes a while shows the progress dialog; its Cancel button drops the
// result and keeps the scene.
void TestMainWindow::slowLoadShowsProgressAndCancelDiscards()
{
    auto window = showWindow(QStringLiteral("slow"));
    QVERIFY(waitForScene(*window, MainWindow::defaultSource()));
    // 30 copies of the pushed sphere, ~220k triangles: loading and validating take a while.
    TriangleMesh big;
    const TriangleMesh sphere = makeDemoScene("pushed-sphere")->objects.front().mesh;
    for (int copy = 0; copy < 30; ++copy) {
        TriangleMesh shifted = sphere;
        for (glm::vec3& p : shifted.positions)
            p.x += 5.0f * float(copy);
        appendMesh(big, shifted);
    }
    const QString slow = path(QStringLiteral("slow.obj"));
    QVERIFY(test::writePlainObj(big, slow));

    QSignalSpy loaded(window.get(), &MainWindow::sceneLoaded);
    QSignalSpy canceled(window->sceneLoader(), &SceneLoader::canceled);
    window->sceneLoader()->setProgressDelay(0);
    window->openSource(slow);
    QPointer<QProgressDialog> progress = window->sceneLoader()->progressDialog();
    QVERIFY(progress);
    QVERIFY(QTest::qWaitFor([&] { return progress && progress->isVisible(); }, kWaitMs));
    QVERIFY(window->isLoading());
    auto* cancel = progress->findChild<QPushButton*>();
    QVERIFY(cancel);
    QTest::mouseClick(cancel, Qt::LeftButton);
    QCOMPARE(canceled.count(), 1);
    QVERIFY(!window->isLoading());
    QVERIFY(QTest::qWaitFor([&] { return !progress || !progress->isVisible(); }, kWaitMs));
    QVERIFY(window->sceneLoader()->progressDialog() == nullptr);
    // The worker runs to its end; its result must be dropped.
    QVERIFY(QThreadPool::globalInstance()->waitForDone(kWaitMs));
    QTest::qWait(50); // deliver the finished notification
    QCOMPARE(loaded.count(), 0);
    QCOMPARE(QString::fromStdString(window->scene()->source), MainWindow::defaultSource());
}

namespace {

bool sameCamera(const Camera& a, const Camera& b)
{
    return glm::length(a.eye - b.eye) < 1e-12 && glm::length(a.target - b.target) < 1e-12;
}

void sendWheel(QWidget* widget, QPoint position, int angleDelta, Qt::KeyboardModifiers modifiers = {})
{
    QWheelEvent wheel(position, widget->mapToGlobal(position), QPoint(), QPoint(0, angleDelta), Qt::NoButton, modifiers,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &wheel);
}

} // namespace

// Orbit, pan, zoom and fit from real mouse and key events; a frame follows each change
// and none comes while nothing changes.
void TestMainWindow::mouseAndKeysMoveTheCamera()
{
    auto window = showWindow(QStringLiteral("mouse"));
    QVERIFY(waitForScene(*window, MainWindow::defaultSource()));
    QVERIFY(waitForFrame(*window));
    ViewportWidget* viewport = window->viewport();
    const auto frameShows = [&](const Camera& camera) {
        return QTest::qWaitFor(
            [&] { return viewport->lastFrame() && sameCamera(viewport->lastFrame()->camera, camera); }, kWaitMs);
    };
    QSignalSpy frames(viewport, &ViewportWidget::frameRendered);
    QTest::qWait(300);
    QCOMPARE(frames.count(), 0); // idle: no busy loop

    const Camera start = viewport->camera();
    QTest::mousePress(viewport, Qt::LeftButton, {}, QPoint(100, 100));
    QTest::mouseMove(viewport, QPoint(160, 90));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, QPoint(160, 90));
    const Camera orbited = viewport->camera();
    QVERIFY(!sameCamera(orbited, start));
    QVERIFY(glm::length(orbited.target - start.target) < 1e-12);
    QVERIFY(std::abs(glm::length(orbited.eye - orbited.target) - glm::length(start.eye - start.target)) < 1e-9);
    QVERIFY(frameShows(orbited));

    QTest::mousePress(viewport, Qt::RightButton, {}, QPoint(100, 100));
    QTest::mouseMove(viewport, QPoint(120, 110));
    QTest::mouseRelease(viewport, Qt::RightButton, {}, QPoint(120, 110));
    const Camera panned = viewport->camera();
    QVERIFY(glm::length(panned.target - orbited.target) > 1e-6);
    QVERIFY(glm::length((panned.eye - panned.target) - (orbited.eye - orbited.target)) < 1e-9);

    sendWheel(viewport, QPoint(128, 96), 240);
    const Camera zoomed = viewport->camera();
    QVERIFY(glm::length(zoomed.eye - zoomed.target) < 0.9 * glm::length(panned.eye - panned.target));
    QVERIFY(frameShows(zoomed));

    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_F);
    const Camera fitted = viewport->camera();
    const Bounds bounds = window->scene()->scene.worldBounds();
    QVERIFY(glm::length(fitted.target - bounds.center()) < 1e-9);
    QVERIFY(glm::length(glm::normalize(fitted.target - fitted.eye) - glm::normalize(zoomed.target - zoomed.eye)) <
            1e-9);
    QVERIFY(frameShows(fitted));

    QTest::mouseDClick(viewport, Qt::LeftButton, {}, QPoint(50, 50));
    QVERIFY(sameCamera(viewport->camera(), fitted));
}

void TestMainWindow::aboutNamesTheOpenGLRenderer()
{
    auto window = showWindow(QStringLiteral("about"));
    QVERIFY(waitForFrame(*window));
    QAction* about = nullptr;
    for (QAction* menu : window->menuBar()->actions())
        for (QAction* item : menu->menu()->actions())
            about = item->text().contains(QStringLiteral("About")) ? item : about;
    QVERIFY(about);
    MessageBoxCloser closer;
    about->trigger(); // modal: returns once the closer pressed OK
    QVERIFY(!closer.seen().isEmpty());
    const QString text = closer.seen().front();
    QVERIFY2(text.contains(window->viewport()->capabilities()->renderer.toHtmlEscaped()), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral(TRIMLAB_VERSION_FOR_TEST)));
}

namespace {

/// Pixels `icon` draws at `size` that are not transparent (0: nothing drawn, e.g. when
/// the resource is missing or Qt's SVG icon engine is not installed).
int drawnPixels(const QIcon& icon, int size)
{
    const QImage image = icon.pixmap(size, size).toImage().convertToFormat(QImage::Format_ARGB32);
    int drawn = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            drawn += qAlpha(image.pixel(x, y)) > 0 ? 1 : 0;
    return drawn;
}

} // namespace

// The application icon and every tool bar action's icon come from resources/icons (SVG,
// drawn by the icon engine of Qt's SVG module).
void TestMainWindow::iconsAreDrawn()
{
    auto window = showWindow(QStringLiteral("icons"));
    QVERIFY(drawnPixels(window->windowIcon(), 48) > 48 * 48 / 2);
    auto* tools = window->findChild<QToolBar*>(QStringLiteral("designToolBar"));
    QVERIFY(tools);
    QCOMPARE(tools->actions().size(), 5);
    for (QAction* action : tools->actions())
        QVERIFY2(drawnPixels(action->icon(), 24) > 24, qPrintable(action->text()));
}

// What a newcomer looks for: View ▸ View From presets (front, top, … on the keypad) turn the
// camera to look along the axis; View lists every panel, the Surface panel included;
// Help has a user guide and a shortcuts list read from the menus; a long status message
// is available in full as the status bar's tooltip.
void TestMainWindow::viewPresetsAndHelp()
{
    auto window = showWindow(QStringLiteral("presets"));
    QVERIFY(waitForScene(*window, MainWindow::defaultSource()));
    QVERIFY(waitForFrame(*window));
    ViewportWidget* viewport = window->viewport();
    const auto lookDirection = [&] {
        const Camera camera = viewport->camera();
        return glm::normalize(camera.target - camera.eye);
    };
    window->activateWindow(); // shortcuts reach the active window only
    QVERIFY(QTest::qWaitForWindowActive(window.get()));
    viewport->setFocus();
    QTest::keyClick(viewport, Qt::Key_7, Qt::KeypadModifier); // top, on the keypad
    QVERIFY2(glm::dot(lookDirection(), glm::dvec3(0.0, -1.0, 0.0)) > 0.999, "the top view does not look down");
    QTest::keyClick(viewport, Qt::Key_1); // front
    QVERIFY(glm::dot(lookDirection(), glm::dvec3(0.0, 0.0, -1.0)) > 0.999);
    // The orientation axes turn with the view: from the front x points right, y up and z
    // at the viewer (a dot).
    auto* axes = window->findChild<OrientationAxes*>(QStringLiteral("orientationAxes"));
    QVERIFY(axes && axes->isVisible());
    {
        const QPointF centre = axes->centre();
        const std::array<QPointF, 3> ends = axes->axisEnds();
        QVERIFY(ends[0].x() > centre.x() + 20.0 && std::abs(ends[0].y() - centre.y()) < 1.0);
        QVERIFY(ends[1].y() < centre.y() - 20.0 && std::abs(ends[1].x() - centre.x()) < 1.0);
        QVERIFY(QLineF(ends[2], centre).length() < 1.0);
    }
    QTest::keyClick(viewport, Qt::Key_1, Qt::ControlModifier); // back
    QVERIFY(glm::dot(lookDirection(), glm::dvec3(0.0, 0.0, 1.0)) > 0.999);
    child<QAction>(window.get(), "viewRightAction")->trigger();
    QVERIFY(glm::dot(lookDirection(), glm::dvec3(-1.0, 0.0, 0.0)) > 0.999);
    QVERIFY(waitForFrame(*window));

    QStringList panels;
    for (QAction* menu : window->menuBar()->actions())
        if (menu->menu() && menu->menu()->title() == QStringLiteral("&View"))
            for (QAction* action : menu->menu()->actions())
                panels << action->text();
    QVERIFY2(panels.contains(QStringLiteral("S&urface Panel")), qPrintable(panels.join(QLatin1Char('|'))));

    child<QAction>(window.get(), "keyboardShortcutsAction")->trigger();
    auto* table = window->findChild<QTableWidget*>(QStringLiteral("shortcutsTable"));
    QVERIFY(table);
    QStringList listed;
    for (int r = 0; r < table->rowCount(); ++r)
        listed << table->item(r, 1)->text() + QLatin1Char('=') + table->item(r, 2)->text();
    QVERIFY2(
        listed.contains(QStringLiteral("Open…=") + QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText)),
        qPrintable(listed.join(QLatin1Char('|'))));
    QVERIFY2(listed.contains(QStringLiteral("Fit to View=F")), qPrintable(listed.join(QLatin1Char('|'))));
    table->window()->close();
    child<QAction>(window.get(), "userGuideAction")->trigger();
    auto* guide = window->findChild<QTextBrowser*>(QStringLiteral("userGuideText"));
    QVERIFY(guide && guide->toPlainText().contains(QStringLiteral("winding number")));
    guide->window()->close();

    const QString message = window->statusBar()->currentMessage();
    QVERIFY(!message.isEmpty());
    QCOMPARE(window->statusBar()->toolTip(), message);

    // View ▸ Mesh Statistics shows what `trimlab info` prints for the shown scene.
    child<QAction>(window.get(), "meshStatisticsAction")->trigger();
    auto* statistics = window->findChild<QTextEdit*>(QStringLiteral("sceneStatisticsText"));
    QVERIFY(statistics);
    const LoadedScene& shown = *window->scene();
    QVERIFY(statistics->toPlainText().contains(
        QString::fromStdString(formatReport(shown.reports.front(), shown.scene.objects.front().name))));
    statistics->window()->close();
    // Hiding the axes persists.
    child<QAction>(window.get(), "showAxesAction")->trigger();
    QVERIFY(!axes->isVisible());
    QVERIFY(!QSettings(path(QStringLiteral("presets.ini")), QSettings::IniFormat)
                 .value(QStringLiteral("view/showAxes"))
                 .toBool());
}

TRIMLAB_WIDGET_TEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
