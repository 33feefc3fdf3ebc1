#pragma once
/// \file
/// The real main window on screen for a widget test: its settings in a test's own INI
/// file, a fixed viewport size so that frames compare with the reference pixel for pixel.

#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include <QSize>
#include <QString>
#include <QtTest>

#include <memory>

namespace trimlab::test {

/// A main window with its settings in the INI file `ini`, shown, its viewport fixed at
/// `viewportSize` (an invalid size keeps the layout's). Warns when the window is not
/// exposed; the test's own checks then fail with their reasons.
inline std::unique_ptr<ui::MainWindow> showMainWindow(const QString& ini, QSize viewportSize)
{
    auto window = std::make_unique<ui::MainWindow>(ini);
    if (viewportSize.isValid())
        window->viewport()->setFixedSize(viewportSize);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        qWarning("main window not exposed");
    return window;
}

} // namespace trimlab::test
