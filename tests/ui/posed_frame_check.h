#pragma once
/// \file
/// The viewport of the main window against the exact CPU reference while an animation is
/// shown, shared by the Timeline/Segmentation and Skinning panel tests: the reference
/// ray-casts the window's scene with object 0 moved to given positions (a pose, or a
/// skinned approximation of one), with the frame's own camera, size and settings.

#include "image_artifacts.h"
#include "trim_comparison.h"

#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include "core/trim/reference_renderer.h"

#include <glm/vec3.hpp>

#include <QSignalSpy>
#include <QString>
#include <QtTest>

#include <functional>
#include <optional>
#include <vector>

namespace trimlab::test {

/// Runs `action` and waits up to `timeoutMs` for a frame rendered after it.
inline bool waitForFrameAfter(ui::MainWindow& window, const std::function<void()>& action, int timeoutMs)
{
    QSignalSpy frames(window.viewport(), &ui::ViewportWidget::frameRendered);
    action();
    return QTest::qWaitFor([&] { return !frames.isEmpty(); }, timeoutMs);
}

/// The viewport's last frame against the reference of the window's scene with object 0 at
/// `positions` (#V of object 0's mesh), by the render tests' criteria: ≥ 99.9 % of the
/// compared pixels agree and ≤ 5 % are excluded; a frame covering fewer than 1/40 of its
/// pixels fails (it would prove nothing). Returns nullopt when they agree, else the
/// reason; a disagreement writes <name>-actual/expected/diff.png and names them.
inline std::optional<QString> posedFrameDisagreement(ui::MainWindow& window, const std::vector<glm::vec3>& positions,
                                                     const QString& name)
{
    const ui::ViewportFrame frame = *window.viewport()->lastFrame();
    const TrimImage actual = window.viewport()->readTrimImage();
    Scene posed = window.scene()->scene;
    posed.objects.front().mesh.positions = positions;
    const ReferenceRenderer reference(posed);
    const int width = frame.pixelSize.width();
    const int height = frame.pixelSize.height();
    const ReferenceResult expected = reference.render(frame.camera, width, height, frame.settings);
    const TrimComparison comparison =
        compareTrimImages(actual, expected.trim, expected.diagnostics, {},
                          referenceTieCheck(reference, frame.camera, width, height, frame.settings));
    qInfo("%s: %s", qPrintable(name), qPrintable(comparison.summary()));
    if (comparison.coveredPixels < width * height / 40)
        return QStringLiteral("%1: only %2 pixels covered").arg(name).arg(comparison.coveredPixels);
    if (comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05)
        return std::nullopt;
    const QString files = writeComparisonArtifacts(name, trimImageToPicture(actual), trimImageToPicture(expected.trim),
                                                   comparison.disagreementMask);
    return name + ": " + comparison.summary() + "; " + files;
}

} // namespace trimlab::test
