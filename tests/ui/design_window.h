#pragma once
/// \file
/// The main window set up for the designer workflow, shared by the design tests
/// (tst_design_workflow.cpp), the drag benchmark (bench_design_drag.cpp) and the tests of
/// what the window shows (window/tst_shown_frames.cpp, window/tst_mesh_statistics.cpp),
/// with a brush stroke as a user drags it.

#include "named_child.h"
#include "plain_obj.h"
#include "shown_main_window.h"

#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include "core/mesh/triangle_mesh.h"

#include <QPoint>
#include <QSettings>
#include <QSignalSpy>
#include <QString>
#include <QtTest>

#include <memory>

namespace trimlab::test {

inline constexpr int kWaitMs = 30000;

/// A main window with its settings in the INI file `ini`, shown and active, its viewport
/// fixed at `viewportSize`. No clipping plane (the brush grabs the outside of the mesh)
/// and a brush radius of 0.4 bounding radii.
inline std::unique_ptr<ui::MainWindow> showDesignWindow(const QString& ini, QSize viewportSize)
{
    {
        QSettings settings(ini, QSettings::IniFormat);
        settings.setValue(QStringLiteral("render/clipEnabled"), false);
        settings.setValue(QStringLiteral("brush/radiusFraction"), 0.4);
    }
    auto window = showMainWindow(ini, viewportSize);
    // Shortcuts (B, N, Ctrl+Z) go to the active window only.
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window.get()))
        qWarning("main window not active");
    return window;
}

/// Opens `source` and waits until its design session exists and a frame was shown, and
/// the window is active again: a slow load shows a progress dialog, which takes the
/// activation, and the shortcuts the tests press next go to the active window only.
inline bool openDesignAndWait(ui::MainWindow& window, const QString& source)
{
    window.openSource(source);
    const bool opened = QTest::qWaitFor(
        [&] {
            return !window.isLoading() && window.scene() && window.scene()->source == source.toStdString() &&
                   window.designWorkspace()->session() && window.viewport()->lastFrame().has_value();
        },
        kWaitMs);
    window.activateWindow();
    if (opened && !QTest::qWaitForWindowActive(&window, kWaitMs))
        qWarning("the main window is not active after opening %s; shortcuts will not reach it", qPrintable(source));
    return opened;
}

/// A left drag from `from` to `to` in `steps` moves, as QTest sends it.
inline void brushDrag(QWidget* viewport, QPoint from, QPoint to, int steps = 6)
{
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    for (int i = 1; i <= steps; ++i)
        QTest::mouseMove(viewport, from + (to - from) * i / steps);
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, to);
}

/// A brush drag from the viewport's centre by `offset`; true once the history has one
/// frame more.
inline bool strokeAtCentre(ui::MainWindow& window, QPoint offset)
{
    const ui::DesignSession* session = window.designWorkspace()->session();
    const int before = session->timeline().frameCount();
    const QPoint centre(window.viewport()->width() / 2, window.viewport()->height() / 2);
    brushDrag(window.viewport(), centre, centre + offset);
    return QTest::qWaitFor([&] { return session->timeline().frameCount() == before + 1; }, kWaitMs);
}

/// Waits for the viewport's next frame; adds the frames seen to `seen`.
inline bool waitForNewFrame(ui::MainWindow& window, int& seen)
{
    QSignalSpy spy(window.viewport(), &ui::ViewportWidget::frameRendered);
    const bool ok = spy.wait(kWaitMs);
    seen += int(spy.count());
    return ok;
}

/// Returns once `viewport` rendered no frame for `quietMs` (updates still queued, e.g. the
/// end of a drag, have arrived), so that its last frame is the one it keeps showing.
inline void waitUntilViewIdle(ui::ViewportWidget& viewport, int quietMs = 300)
{
    QSignalSpy frames(&viewport, &ui::ViewportWidget::frameRendered);
    do {
        frames.clear();
        QTest::qWait(quietMs);
    } while (!frames.isEmpty());
}

} // namespace trimlab::test
