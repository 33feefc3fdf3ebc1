#pragma once
/// \file
/// The viewport of the main window against the exact CPU reference of what it should show,
/// shared by the Timeline/Segmentation and Skinning panel tests and the tests of what the
/// window shows (window/tst_shown_frames.cpp): the reference ray-casts the window's scene
/// with object 0 moved to given positions (a pose, a skinned approximation, a skeleton
/// pose, a design frame), or a dynamic rules' chain, with the frame's own camera, size and
/// settings.

#include "image_artifacts.h"
#include "trim_comparison.h"

#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include "core/trim/dynamic_chain.h"
#include "core/trim/dynamic_reference_renderer.h"
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

/// The viewport's last frame and the exact reference of what it should show, with the same
/// camera, size and settings.
struct FrameAgainstReference {
    TrimImage actual;
    ReferenceResult expected;
    TrimComparison comparison;
};

/// The last frame against the reference of the window's scene with object 0 at
/// `positions` (#V of object 0's mesh).
inline FrameAgainstReference posedFrameAgainstReference(ui::MainWindow& window, const std::vector<glm::vec3>& positions)
{
    FrameAgainstReference result;
    result.actual = window.viewport()->readTrimImage(); // first: lastFrame() is then its frame
    const ui::ViewportFrame frame = *window.viewport()->lastFrame();
    Scene posed = window.scene()->scene;
    posed.objects.front().mesh.positions = positions;
    const ReferenceRenderer reference(posed);
    const int width = frame.pixelSize.width();
    const int height = frame.pixelSize.height();
    result.expected = reference.render(frame.camera, width, height, frame.settings);
    result.comparison = compareTrimImages(result.actual, result.expected.trim, result.expected.diagnostics, {},
                                          referenceTieCheck(reference, frame.camera, width, height, frame.settings));
    return result;
}

/// The last frame against the dynamic rules' reference of `chain`.
inline FrameAgainstReference chainFrameAgainstReference(ui::MainWindow& window, const DynamicChain& chain)
{
    FrameAgainstReference result;
    result.actual = window.viewport()->readTrimImage(); // first: lastFrame() is then its frame
    const ui::ViewportFrame frame = *window.viewport()->lastFrame();
    result.expected = DynamicReferenceRenderer(chain).render(frame.camera, frame.pixelSize.width(),
                                                             frame.pixelSize.height(), frame.settings);
    result.comparison = compareTrimImages(result.actual, result.expected.trim, result.expected.diagnostics);
    return result;
}

/// The render tests' criteria: ≥ 99.9 % of the compared pixels agree and ≤ 5 % are
/// excluded; a frame covering fewer than 1/40 of its pixels fails (it would prove
/// nothing). Returns nullopt when they are met, else the reason; a disagreement writes
/// <name>-actual/expected/diff.png and names them.
inline std::optional<QString> frameDisagreement(const FrameAgainstReference& check, const QString& name)
{
    const TrimComparison& comparison = check.comparison;
    qInfo("%s: %s", qPrintable(name), qPrintable(comparison.summary()));
    if (comparison.coveredPixels < check.actual.width * check.actual.height / 40)
        return QStringLiteral("%1: only %2 pixels covered").arg(name).arg(comparison.coveredPixels);
    if (comparison.agreement() >= 0.999 && comparison.excludedFraction() <= 0.05)
        return std::nullopt;
    const QString files = writeComparisonArtifacts(
        name, trimImageToPicture(check.actual), trimImageToPicture(check.expected.trim), comparison.disagreementMask);
    return name + ": " + comparison.summary() + "; " + files;
}

/// The last frame against the reference of the scene with object 0 at `positions`, by
/// frameDisagreement's criteria.
inline std::optional<QString> posedFrameDisagreement(ui::MainWindow& window, const std::vector<glm::vec3>& positions,
                                                     const QString& name)
{
    return frameDisagreement(posedFrameAgainstReference(window, positions), name);
}

} // namespace trimlab::test
