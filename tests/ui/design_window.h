#pragma once
/// \file
/// The main window set up for the designer workflow, shared by the design tests
/// (tst_design_workflow.cpp) and the drag benchmark (bench_design_drag.cpp).

#include "named_child.h"
#include "plain_obj.h"
#include "shown_main_window.h"

#include "design_workspace.h"
#include "main_window.h"
#include "viewport_widget.h"

#include "mesh/triangle_mesh.h"

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

/// Opens `source` and waits until its design session exists and a frame was shown.
inline bool openDesignAndWait(ui::MainWindow& window, const QString& source)
{
    window.openSource(source);
    return QTest::qWaitFor(
        [&] {
            return !window.isLoading() && window.scene() && window.scene()->source == source.toStdString() &&
                   window.designWorkspace()->session() && window.viewport()->lastFrame().has_value();
        },
        kWaitMs);
}

/// Waits for the viewport's next frame; adds the frames seen to `seen`.
inline bool waitForNewFrame(ui::MainWindow& window, int& seen)
{
    QSignalSpy spy(window.viewport(), &ui::ViewportWidget::frameRendered);
    const bool ok = spy.wait(kWaitMs);
    seen += int(spy.count());
    return ok;
}

} // namespace trimlab::test
