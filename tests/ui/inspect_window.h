#pragma once
/// \file
/// The main window set up for the interior-inspection tests (tst_inspect_*.cpp): shown
/// with a small fixed viewport, a scene opened, and the last frame compared with the
/// exact CPU reference for the frame's own scene (model matrices included), camera, size
/// and settings (clip set, caps, CSG, highlights) by the render tests' criteria.

#include "gl_test_context.h"
#include "image_artifacts.h"
#include "named_child.h"
#include "plain_obj.h"
#include "trim_comparison.h"

#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include "render/mfr/fragment_method.h"
#include "core/mesh/triangle_mesh.h"
#include "core/trim/reference_renderer.h"

#include <QDockWidget>
#include <QScrollArea>
#include <QSettings>
#include <QString>
#include <QtTest>

#include <functional>
#include <memory>
#include <optional>

namespace trimlab::test {

inline constexpr QSize kInspectViewportSize(160, 120);
inline constexpr int kInspectWaitMs = 20000;

/// Brings `widget` on screen as a user would before clicking it: raises the tab of its
/// dock and scrolls its panel to it (a click lands where the widget is drawn, so a
/// widget scrolled out of view or behind another tab would miss). Returns `widget`.
template <class T>
T* revealed(T* widget)
{
    if (!widget)
        return widget;
    for (QWidget* w = widget; w; w = w->parentWidget())
        if (auto* dock = qobject_cast<QDockWidget*>(w))
            dock->raise();
    QCoreApplication::processEvents();
    for (QWidget* w = widget; w; w = w->parentWidget())
        if (auto* scroll = qobject_cast<QScrollArea*>(w))
            scroll->ensureWidgetVisible(widget);
    QCoreApplication::processEvents();
    if (!widget->isVisible())
        qWarning("%s is not visible", qPrintable(widget->objectName()));
    return widget;
}

/// Waits until the viewport's last frame satisfies `ready`.
/// On a timeout, warns with the viewport's error message (e.g. a method refusing CSG).
inline bool waitForFrame(ui::MainWindow& window, const std::function<bool(const ui::ViewportFrame&)>& ready)
{
    const bool rendered = QTest::qWaitFor(
        [&] {
            const auto& frame = window.viewport()->lastFrame();
            return frame && ready(*frame);
        },
        kInspectWaitMs);
    if (!rendered)
        qWarning("no such frame; viewport error: %s", qPrintable(window.viewport()->errorMessage()));
    return rendered;
}

/// A main window with its settings in the INI file `ini`, shown, active, its viewport
/// fixed at kInspectViewportSize, showing `source` with a first frame rendered.
inline std::unique_ptr<ui::MainWindow> showInspectWindow(const QString& ini, const QString& source)
{
    auto window = std::make_unique<ui::MainWindow>(ini);
    window->viewport()->setFixedSize(kInspectViewportSize);
    window->openSource(source); // before the event loop runs: the default demo is not opened
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get()))
        qWarning("main window not exposed");
    const bool shown = QTest::qWaitFor(
        [&] {
            const auto& frame = window->viewport()->lastFrame();
            return !window->isLoading() && window->scene() && window->scene()->source == source.toStdString() &&
                   frame && frame->scene && frame->scene.get() == &window->scene()->scene;
        },
        kInspectWaitMs);
    if (!shown)
        qWarning("%s was not shown", qPrintable(source));
    // Ctrl+Z goes to the active window only; activated after the load, whose progress
    // dialog (shown when loading is slow) takes the activation.
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window.get(), kInspectWaitMs))
        qWarning("main window not active");
    return window;
}

/// The reference for the last frame (its scene, camera, size and settings).
inline ReferenceResult referenceOfLastFrame(ui::MainWindow& window)
{
    const ui::ViewportFrame& frame = *window.viewport()->lastFrame();
    const ReferenceRenderer reference(*frame.scene);
    return reference.render(frame.camera, frame.pixelSize.width(), frame.pixelSize.height(), frame.settings);
}

/// The last frame against the reference by the render tests' criteria (≥ 99.9 % of the
/// compared pixels agree, ≤ 5 % excluded); nullopt when it agrees. Fails too when fewer
/// than `minCoveredFraction` of the pixels are covered (a blank frame proves nothing).
/// On failure writes <name>-actual/expected/diff.png and names them.
inline std::optional<QString> inspectDisagreement(ui::MainWindow& window, const QString& name,
                                                  double minCoveredFraction = 0.05)
{
    const TrimImage actual = window.viewport()->readTrimImage(); // first: lastFrame() is then its frame
    const ui::ViewportFrame frame = *window.viewport()->lastFrame();
    const ReferenceRenderer reference(*frame.scene);
    const int width = frame.pixelSize.width();
    const int height = frame.pixelSize.height();
    const ReferenceResult expected = reference.render(frame.camera, width, height, frame.settings);
    const TrimComparison comparison =
        compareTrimImages(actual, expected.trim, expected.diagnostics, {},
                          referenceTieCheck(reference, frame.camera, width, height, frame.settings));
    const bool bounded = render::methodInfo(frame.stats.method).bounded;
    const auto violation = agreementViolation(comparison, {}, bounded, frame.stats.counts.fragmentsLost);
    qInfo("%s: %s", qPrintable(name), qPrintable(comparison.summary()));
    const QString files = violation || comparison.coveredPixels < minCoveredFraction * width * height
                              ? writeComparisonArtifacts(name, trimImageToPicture(actual),
                                                         trimImageToPicture(expected.trim), comparison.disagreementMask)
                              : QString();
    if (comparison.coveredPixels < minCoveredFraction * width * height)
        return QStringLiteral("%1: only %2 pixels covered; %3").arg(name).arg(comparison.coveredPixels).arg(files);
    if (!violation)
        return std::nullopt;
    return name + ": " + QString::fromStdString(*violation) + "; " + comparison.summary() + "; " + files;
}

/// Pixels whose answer (coverage, object, primitive, cap plane) differs between `a` and
/// `b` (same size): how much an edit changed the frame.
inline int changedPixels(const TrimImage& a, const TrimImage& b)
{
    if (a.width != b.width || a.height != b.height)
        return a.width * a.height;
    int changed = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const TrimPixel& p = a.at(x, y);
            const TrimPixel& q = b.at(x, y);
            if (p.covered() != q.covered() || p.objectId != q.objectId || p.primitiveId != q.primitiveId ||
                p.capPlane != q.capPlane)
                ++changed;
        }
    return changed;
}

} // namespace trimlab::test
