// Drag-update latency of the designer's brush in the real main window (not a test: it
// never fails on speed and is not registered with CTest). Run under Xvfb:
//   xvfb-run -a build/tests/ui/bench_design_drag MESH [WIDTHxHEIGHT]
// MESH is a mesh file (e.g. ../shared/data/static/odedstein-bunny_hr.obj.gz) or
// "torus-100k" for a generated torus of 100,000 vertices. Prints, for the static and the
// dynamic rules: the press (pick + BrushStroke), the median drag update (stroke + hand-off
// to the viewport), the median time from a mouse move to the frame shown and the trim
// render's share, then the homogeneous confluent check at two presses.
#include "ui/design/design_workspace.h"
#include "design_window.h"

#include "ui/design/brush_tool.h"
#include "ui/design/design_session.h"
#include "core/scene/shape_generators.h"

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace trimlab;

namespace {

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

void measureDrags(ui::MainWindow& window, QSize size, bool dynamic)
{
    ui::ViewportWidget* viewport = window.viewport();
    test::child<QComboBox>(&window, "classificationComboBox")->setCurrentIndex(dynamic ? 1 : 0);
    viewport->update();
    int frames = 0;
    (void)test::waitForNewFrame(window, frames);
    const QPoint centre(size.width() / 2, size.height() / 2);
    QElapsedTimer press;
    press.start();
    QTest::mousePress(viewport, Qt::LeftButton, {}, centre);
    const double pressMs = double(press.nsecsElapsed()) * 1e-6;
    std::vector<double> update, total, render;
    for (int i = 1; i <= 20; ++i) {
        QSignalSpy arrived(viewport, &ui::ViewportWidget::frameRendered);
        QElapsedTimer timer;
        timer.start();
        QTest::mouseMove(viewport, centre + QPoint(i, -i));
        viewport->repaint(); // the frame the move asked for, now
        QCoreApplication::processEvents();
        if (arrived.isEmpty()) // pipelined: the frame is shown once the GPU has drawn it
            (void)arrived.wait(10000);
        total.push_back(double(timer.nsecsElapsed()) * 1e-6);
        update.push_back(window.designWorkspace()->brushTool()->lastUpdateMilliseconds());
        render.push_back(viewport->lastFrame()->stats.wallMilliseconds);
    }
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, centre + QPoint(20, -20));
    std::printf("%s: %zu vertices, press %.1f ms, drag update median %.2f ms, move to frame shown median %.1f ms, "
                "of which the trim render %.1f ms\n",
                dynamic ? "dynamic rules" : "static rule",
                window.designWorkspace()->session()->topology().vertexCount(), pressMs, median(update), median(total),
                median(render));
}

} // namespace

int main(int argc, char** argv)
{
    QApplication application(argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_design_drag MESH|torus-100k [WIDTHxHEIGHT]\n");
        return 2;
    }
    QSize size(640, 480);
    if (argc > 2 && std::sscanf(argv[2], "%dx%d", &size.rwidth(), &size.rheight()) != 2) {
        std::fprintf(stderr, "bad size '%s'\n", argv[2]);
        return 2;
    }
    QTemporaryDir dir;
    QString mesh = QString::fromLocal8Bit(argv[1]);
    if (mesh == QStringLiteral("torus-100k")) {
        mesh = dir.filePath(QStringLiteral("torus-100k.obj"));
        if (!test::writePlainObj(makeTorus(glm::dvec3(0.0), 1.0, 0.4, 400, 250), mesh)) {
            std::fprintf(stderr, "could not write %s\n", qPrintable(mesh));
            return 1;
        }
    }
    auto window = test::showDesignWindow(dir.filePath(QStringLiteral("bench.ini")), size);
    if (!test::openDesignAndWait(*window, mesh)) {
        std::fprintf(stderr, "could not open %s as a design\n", qPrintable(mesh));
        return 1;
    }
    window->designWorkspace()->brushAction()->setChecked(true);
    measureDrags(*window, size, false);
    measureDrags(*window, size, true);
    // The homogeneous confluent check at a press: chain + CPU reference built, then rays.
    window->designWorkspace()->startNewSet(DynamicRule::HomogeneousConfluent);
    const QPoint centre(size.width() / 2, size.height() / 2);
    for (int press = 0; press < 2; ++press) {
        QTest::mousePress(window->viewport(), Qt::LeftButton, {}, centre);
        QTest::mouseRelease(window->viewport(), Qt::LeftButton, {}, centre);
        std::printf("homogeneous confluent check at press %d: %.1f ms\n", press + 1,
                    window->designWorkspace()->lastTrimCheckMilliseconds());
    }
    return 0;
}
