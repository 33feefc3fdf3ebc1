// Clipping planes, caps and highlights as a user sets them in the Render panel: "None",
// "Box" and two planes of the box moved inward by typing their offsets, capping with a
// pattern, collision and coplanar highlighting with their counts in the status bar, and
// the choices saved with the scene's project (not carried into a new window's demo).
// Every frame is compared with the exact CPU reference for its own scene, camera, size
// and settings.
#include "ui/render_panel/render_workspace.h"
#include "ui/design/design_workspace.h"
#include "ui/design/project_files.h"
#include "inspect_window.h"
#include "test_paths.h"

#include "ui/render_panel/clip_set_editor.h"
#include "ui/render_panel/frame_stats_labels.h"
#include "ui/render_panel/render_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QTemporaryDir>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

namespace {

const QString kTrio = QStringLiteral("demo:csg-trio");

void typeValue(QDoubleSpinBox* spin, const QString& text)
{
    revealed(spin)->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Return);
}

/// Clicks a check box or radio button on its indicator (a click beside its text, in a
/// wide form row, would miss it).
void clickButton(QAbstractButton* button)
{
    QTest::mouseClick(revealed(button), Qt::LeftButton, {}, QPoint(6, button->height() / 2));
}

int enabledPlanes(const ViewportFrame& frame)
{
    return frame.settings.clipSet().enabledCount();
}

} // namespace

class TestInspectClip : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void boxShrunkThroughTheEditorMatchesTheReference();
    void highlightCountsReachTheStatusBar();
    void inspectionChoicesPersist();

private:
    QTemporaryDir m_dir;
};

void TestInspectClip::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

// None clears the first-start plane; Box puts six planes around the scene (the picture
// stays whole); typing two offsets cuts the box open on x and z, with caps.
void TestInspectClip::boxShrunkThroughTheEditorMatchesTheReference()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("box.ini")), kTrio);
    auto* none = child<QPushButton>(window.get(), "clipNoneButton");
    auto* box = child<QPushButton>(window.get(), "clipBoxButton");
    QVERIFY(none && box);
    QTest::mouseClick(revealed(none), Qt::LeftButton);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return enabledPlanes(f) == 0; }));
    const TrimImage whole = window->viewport()->readTrimImage();

    QTest::mouseClick(revealed(box), Qt::LeftButton);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return enabledPlanes(f) == 6; }));
    for (int i = 0; i < kMaxClipPlanes; ++i)
        QVERIFY(child<QCheckBox>(window.get(), qPrintable(QStringLiteral("clipPlaneEnabled%1").arg(i)))->isChecked());
    QVERIFY2(changedPixels(window->viewport()->readTrimImage(), whole) < 20, "the box must not cut the scene");
    auto failure = inspectDisagreement(*window, QStringLiteral("box-whole"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    // Plane 1 keeps x >= lower: move it to x >= 0.2 (n = +x, offset -0.2). Plane 6 keeps
    // z <= upper: move it to z <= 0.3 (n = -z, offset 0.3).
    auto* offset = child<QDoubleSpinBox>(window.get(), "clipOffsetSpin");
    QVERIFY(offset);
    QCOMPARE(window->renderWorkspace()->panel()->clipSetEditor()->selectedPlane(), 0);
    typeValue(offset, QStringLiteral("-0.2"));
    clickButton(child<QRadioButton>(window.get(), "clipPlaneSelect5"));
    QCOMPARE(window->renderWorkspace()->panel()->clipSetEditor()->selectedPlane(), 5);
    typeValue(offset, QStringLiteral("0.3"));
    clickButton(child<QCheckBox>(window.get(), "capCheckBox"));
    const auto shrunk = [](const ViewportFrame& f) {
        const ClipSet set = f.settings.clipSet();
        return set.planes[0].offset == -0.2 && set.planes[5].offset == 0.3 && set.planes[5].normal.z == -1.0 &&
               f.settings.cap.enabled;
    };
    QVERIFY(waitForFrame(*window, shrunk));
    const ViewportFrame frame = *window->viewport()->lastFrame();
    QVERIFY(frame.stats.counts.capPixels > 0);
    QVERIFY(changedPixels(window->viewport()->readTrimImage(), whole) > 500);
    failure = inspectDisagreement(*window, QStringLiteral("box-shrunk-capped"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    const QString shot = QString::fromStdString((outputDir() / "clip-box.png").string());
    QVERIFY(window->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));
}

// Collisions of the trio (the ball and the ring cross the pushed sphere) and coplanar
// counts: the status bar shows the frame's counts, and the frame agrees with the reference
// (which compares the collision flag and coplanar count of every pixel).
void TestInspectClip::highlightCountsReachTheStatusBar()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("highlight.ini")), kTrio);
    auto* label = child<QLabel>(window.get(), "highlightLabel");
    QVERIFY(label);
    QVERIFY(!label->isVisibleTo(window.get()));
    // The cut shows surfaces inside the other objects (unclipped, only the outer hull shows).
    clickButton(child<QCheckBox>(window.get(), "clipPlaneEnabled0"));
    clickButton(child<QCheckBox>(window.get(), "highlightCollisionsCheckBox"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.highlight.collisions; }));
    const std::uint64_t collisions = window->viewport()->lastFrame()->stats.counts.collisionPixels;
    QVERIFY(collisions > 0);
    QVERIFY(label->isVisibleTo(window.get()));
    QCOMPARE(label->text(), QStringLiteral("collisions %1 px").arg(QLocale().toString(qulonglong(collisions))));
    int referenceCollisions = 0;
    for (const TrimPixel& pixel : referenceOfLastFrame(*window).trim.pixels)
        referenceCollisions += pixel.collision ? 1 : 0;
    QVERIFY(referenceCollisions > 0);
    auto failure = inspectDisagreement(*window, QStringLiteral("highlight-collisions"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    clickButton(child<QCheckBox>(window.get(), "highlightCoplanarCheckBox"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.highlight.coplanar; }));
    QVERIFY2(label->text().contains(QStringLiteral("coplanar")), qPrintable(label->text()));
    failure = inspectDisagreement(*window, QStringLiteral("highlight-both"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

// Cap pattern and spacing, the highlight toggles and the box planes survive into a new
// window (the CSG expression belongs to the scene and is not stored).
void TestInspectClip::inspectionChoicesPersist()
{
    const QString ini = m_dir.filePath(QStringLiteral("persist.ini"));
    const QString project = m_dir.filePath(QStringLiteral("persist.trimlab"));
    {
        auto window = showInspectWindow(ini, kTrio);
        QTest::mouseClick(revealed(child<QPushButton>(window.get(), "clipBoxButton")), Qt::LeftButton);
        clickButton(child<QCheckBox>(window.get(), "capCheckBox"));
        auto* pattern = child<QComboBox>(window.get(), "capPatternComboBox");
        QTest::keyClick(revealed(pattern), Qt::Key_Down); // hatched -> striped
        typeValue(child<QDoubleSpinBox>(window.get(), "capSpacingSpin"), QStringLiteral("7.5"));
        clickButton(child<QCheckBox>(window.get(), "highlightCoplanarCheckBox"));
        QCOMPARE(window->viewport()->trimSettings().cap.pattern, CapPattern::Striped);
        QString error;
        QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(project, &error), qPrintable(error));
        window->close();
    }
    // They belong to the scene saved: a new window opening the demo starts without them,
    // and the project brings them back.
    auto window = showInspectWindow(ini, kTrio);
    const RenderChoices fresh = window->renderWorkspace()->panel()->renderChoices();
    QVERIFY(!fresh.trim.cap.enabled);
    QCOMPARE(fresh.trim.clipSet().enabledCount(), 0);
    QVERIFY(!fresh.trim.highlight.coplanar);
    window->openSource(project);
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) {
        return window->scene()->source == project.toStdString() && f.scene.get() == &window->scene()->scene;
    }));
    const RenderChoices restored = window->renderWorkspace()->panel()->renderChoices();
    QVERIFY(restored.trim.cap.enabled);
    QCOMPARE(restored.trim.cap.pattern, CapPattern::Striped);
    QCOMPARE(restored.capSpacingFraction, 0.075);
    QVERIFY(restored.trim.highlight.coplanar);
    QVERIFY(!restored.trim.highlight.collisions);
    QCOMPARE(restored.trim.clipSet().enabledCount(), 6);
    const double radius = window->scene()->scene.worldBounds().radius();
    QVERIFY(std::abs(window->viewport()->trimSettings().cap.spacing - 0.075 * radius) < 1e-12);
    QCOMPARE(child<QComboBox>(window.get(), "capPatternComboBox")->currentText(), QStringLiteral("Striped"));
}

QTEST_MAIN(TestInspectClip)
#include "tst_inspect_clip.moc"
