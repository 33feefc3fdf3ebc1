// Screenshots of rigs as a user sees them: the real main window opens each mesh, the
// Skeleton panel runs with Target nodes N, and the window is saved as a PNG with the rig
// drawn over the mesh. Not a test (it reads the shared data and takes a while); run by
// hand under Xvfb, for docs/:
//
//     xvfb-run -a -s "-screen 0 1280x1024x24" build/tests/ui/skeleton/rig_screenshots
//         OUT_DIR [--nodes 30] MESH...
//
// Prints each rig's posing measures beside its file name.
#include "named_child.h"
#include "shown_main_window.h"

#include "core/skeleton/rig_measures.h"
#include "render/gl/offscreen_gl_context.h"
#include "ui/common/background_job.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/skeleton/skeleton_workspace.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/window/main_window.h"

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;

namespace {

constexpr int kWaitMs = 120000;

bool openAndWait(MainWindow& window, const QString& path)
{
    QSignalSpy loaded(&window, &MainWindow::sceneLoaded);
    window.openSource(path);
    return QTest::qWaitFor([&] { return !loaded.isEmpty() && !window.isLoading(); }, kWaitMs) &&
           QTest::qWaitFor([&] { return window.viewport()->lastFrame().has_value(); }, kWaitMs);
}

bool runAndWait(SkeletonPanel* panel)
{
    QSignalSpy finished(panel->task(), &BackgroundJobBase::finished);
    QTest::mouseClick(child<QPushButton>(panel, "runSkeletonButton"), Qt::LeftButton);
    return QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs) && panel->result();
}

// "cgal-man" for ".../cgal-man.off.gz".
QString baseName(const QString& path)
{
    QString name = QFileInfo(path).fileName();
    if (name.endsWith(QStringLiteral(".gz")))
        name.chop(3);
    return QFileInfo(name).completeBaseName();
}

int shoot(const QString& outDir, int nodes, const QStringList& meshes)
{
    QTemporaryDir settings;
    auto window = test::showMainWindow(settings.filePath(QStringLiteral("rig-screenshots.ini")), QSize());
    window->resize(1600, 1000);
    int failures = 0;
    for (const QString& mesh : meshes) {
        if (!openAndWait(*window, mesh)) {
            std::fprintf(stderr, "%s: did not open\n", qPrintable(mesh));
            ++failures;
            continue;
        }
        child<QDockWidget>(window.get(), "skeletonDock")->raise();
        SkeletonPanel* panel = window->skeletonWorkspace()->panel();
        child<QSpinBox>(panel, "skeletonNodesSpinBox")->setValue(nodes);
        if (!runAndWait(panel)) {
            std::fprintf(stderr, "%s: the skeleton did not run\n", qPrintable(mesh));
            ++failures;
            continue;
        }
        QSignalSpy frames(window->viewport(), &ViewportWidget::frameRendered);
        window->viewport()->update();
        if (!QTest::qWaitFor([&] { return !frames.isEmpty(); }, kWaitMs))
            std::fprintf(stderr, "%s: no new frame\n", qPrintable(mesh));
        QTest::qWait(300); // the overlay and the docks settle
        const QString file = QDir(outDir).filePath(QStringLiteral("rig-%1.png").arg(baseName(mesh)));
        if (!window->grab().save(file)) {
            std::fprintf(stderr, "%s: cannot write\n", qPrintable(file));
            ++failures;
            continue;
        }
        std::printf("%s: %s\n", qPrintable(file), describeRigMeasures(panel->result()->rigMeasures).c_str());
    }
    return failures == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(render::OffscreenGlContext::requestedFormat()); // as the GUI does
    QApplication application(argc, argv);
    QStandardPaths::setTestModeEnabled(true); // no recovery files or settings in the user's folders
    QStringList arguments = application.arguments().mid(1);
    int nodes = 30;
    const qsizetype flag = arguments.indexOf(QStringLiteral("--nodes"));
    if (flag >= 0 && flag + 1 < arguments.size()) {
        nodes = arguments[flag + 1].toInt();
        arguments.remove(flag, 2);
    }
    if (arguments.size() < 2 || nodes < 2) {
        std::fprintf(stderr, "usage: rig_screenshots OUT_DIR [--nodes N] MESH...\n");
        return 2;
    }
    const QString outDir = arguments.takeFirst();
    QDir().mkpath(outDir);
    return shoot(outDir, nodes, arguments);
}
