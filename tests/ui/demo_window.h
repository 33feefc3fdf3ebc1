#pragma once
/// \file
/// The main window on its default demo with a fixed-size viewport, and the check of the
/// viewport's last frame against the exact CPU reference — shared by the tests that drive
/// the renderer through the window (tst_method_panel.cpp, tst_context_loss.cpp).

#include "image_artifacts.h"
#include "shown_main_window.h"
#include "trim_comparison.h"

#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include <QString>
#include <QtTest>

#include <memory>
#include <optional>

namespace trimlab::test {

inline constexpr int kDemoWaitMs = 30000;
inline const QString kDefaultDemo = QStringLiteral("demo:pushed-sphere");

/// A main window with its settings in the INI file `ini`, its viewport fixed at
/// `viewportSize`, shown, once the default demo has loaded (a warning when it did not).
inline std::unique_ptr<ui::MainWindow> showDemoWindow(const QString& ini, QSize viewportSize)
{
    auto window = showMainWindow(ini, viewportSize);
    const bool loaded = QTest::qWaitFor(
        [&] {
            return !window->isLoading() && window->scene() && window->scene()->source == kDefaultDemo.toStdString();
        },
        kDemoWaitMs);
    if (!loaded)
        qWarning("the default demo did not load");
    return window;
}

/// The viewport's last frame against the reference for its camera, size and settings,
/// with the render tests' criteria (core/trim/trim_agreement.h); on disagreement the
/// images are written under the test output folder as `name`-*.png. nullopt when it
/// agrees; a frame covering less than a tenth of the view fails too.
inline std::optional<QString> lastFrameDisagreement(ui::MainWindow& window, const QString& name)
{
    const TrimImage actual = window.viewport()->readTrimImage(); // first: lastFrame() is then its frame
    const ui::ViewportFrame frame = *window.viewport()->lastFrame();
    const ReferenceRenderer reference(window.scene()->scene);
    const int width = frame.pixelSize.width();
    const int height = frame.pixelSize.height();
    const ReferenceResult expected = reference.render(frame.camera, width, height, frame.settings);
    const TrimComparison comparison =
        compareTrimImages(actual, expected.trim, expected.diagnostics, {},
                          referenceTieCheck(reference, frame.camera, width, height, frame.settings));
    const bool bounded = render::methodInfo(frame.stats.method).bounded;
    const auto violation = agreementViolation(comparison, {}, bounded, frame.stats.counts.fragmentsLost);
    qInfo("%s: %s", qPrintable(name), qPrintable(comparison.summary()));
    if (comparison.coveredPixels < width * height / 10)
        return QStringLiteral("%1: only %2 pixels covered").arg(name).arg(comparison.coveredPixels);
    if (!violation)
        return std::nullopt;
    const QString files = writeComparisonArtifacts(name, trimImageToPicture(actual), trimImageToPicture(expected.trim),
                                                   comparison.disagreementMask);
    return name + ": " + QString::fromStdString(*violation) + "; " + comparison.summary() + "; " + files;
}

} // namespace trimlab::test
