// What the interior-inspection controls persist and show, without a window or OpenGL:
// the six clipping planes, capping and highlighting through the settings store (with
// fallbacks for broken values, field by field), the same through the Render panel's
// widgets, and the clip set editor's Box / None / row toggles.
#include "ui/render_panel/clip_plane_editor.h"
#include "ui/render_panel/clip_set_editor.h"
#include "ui/render_panel/inspect_group.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_settings_store.h"

#include <QApplication>
#include <QCheckBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <limits>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

/// Whether the two sets hold the same planes exactly (enabled flag, normal, offset).
bool sameClipSet(const ClipSet& a, const ClipSet& b)
{
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        const ClipPlane& p = a.planes[std::size_t(i)];
        const ClipPlane& q = b.planes[std::size_t(i)];
        if (p.enabled != q.enabled || p.normal != q.normal || p.offset != q.offset)
            return false;
    }
    return true;
}

/// Choices with every inspection field away from its default.
RenderChoices unusualChoices()
{
    RenderChoices choices = firstStartRenderChoices();
    for (int i = 0; i < kMaxClipPlanes; ++i) {
        ClipPlane& plane = choices.trim.clipPlane(i);
        plane.enabled = i % 2 == 0;
        plane.normal = {0.125 * i, -0.5, 1.0 / 3.0};
        plane.offset = -0.0625 * i - 0.1;
    }
    choices.trim.cap.enabled = true;
    choices.trim.cap.pattern = CapPattern::Solid;
    choices.capSpacingFraction = 0.125;
    choices.trim.highlight = {true, true};
    return choices;
}

} // namespace

class TestInspectSettings : public QObject {
    Q_OBJECT
private slots:
    void init();
    void inspectionChoicesRoundTrip();
    void brokenInspectionValuesFallBack();
    void renderPanelShowsWhatItIsGiven();
    void boxNoneAndRowsEditTheSet();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    [[nodiscard]] QString iniPath() const { return m_dir->filePath(QStringLiteral("settings.ini")); }
};

void TestInspectSettings::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

void TestInspectSettings::inspectionChoicesRoundTrip()
{
    const RenderChoices saved = unusualChoices();
    {
        QSettings settings(iniPath(), QSettings::IniFormat);
        saveRenderChoices(settings, saved);
    }
    const QSettings settings(iniPath(), QSettings::IniFormat);
    const RenderChoices loaded = loadRenderChoices(settings);
    QVERIFY(sameClipSet(loaded.trim.clipSet(), saved.trim.clipSet())); // exact: doubles survive the INI file
    QCOMPARE(loaded.trim.cap.enabled, true);
    QCOMPARE(loaded.trim.cap.pattern, CapPattern::Solid);
    QCOMPARE(loaded.capSpacingFraction, 0.125);
    QCOMPARE(loaded.trim.highlight, saved.trim.highlight);
    QVERIFY(!loaded.trim.csg.enabled()); // never stored
    // Plane 1 keeps the keys of the single plane of earlier versions.
    QCOMPARE(settings.value(QStringLiteral("render/clipOffset")).toDouble(), saved.trim.clip.offset);
}

void TestInspectSettings::brokenInspectionValuesFallBack()
{
    {
        QSettings settings(iniPath(), QSettings::IniFormat);
        saveRenderChoices(settings, unusualChoices());
        settings.setValue(QStringLiteral("render/capPattern"), QStringLiteral("zigzag"));
        settings.setValue(QStringLiteral("render/capSpacingFraction"), 0.0);
        settings.setValue(QStringLiteral("render/clipPlane3/normalX"), 0.0);
        settings.setValue(QStringLiteral("render/clipPlane3/normalY"), 0.0);
        settings.setValue(QStringLiteral("render/clipPlane3/normalZ"), 0.0);
        settings.setValue(QStringLiteral("render/clipPlane4/offset"), QStringLiteral("nan"));
    }
    const QSettings settings(iniPath(), QSettings::IniFormat);
    const RenderChoices loaded = loadRenderChoices(settings);
    const RenderChoices fallback = firstStartRenderChoices();
    QCOMPARE(loaded.trim.cap.pattern, fallback.trim.cap.pattern);
    QCOMPARE(loaded.capSpacingFraction, fallback.capSpacingFraction);
    QVERIFY(loaded.trim.cap.enabled); // the fields around the broken ones are kept
    QCOMPARE(loaded.trim.clipPlane(3).normal, fallback.trim.clipPlane(3).normal);
    QCOMPARE(loaded.trim.clipPlane(3).offset, unusualChoices().trim.clipPlane(3).offset);
    QCOMPARE(loaded.trim.clipPlane(4).offset, fallback.trim.clipPlane(4).offset);
    QCOMPARE(loaded.trim.clipPlane(4).normal, unusualChoices().trim.clipPlane(4).normal);
    {
        QSettings settings2(iniPath(), QSettings::IniFormat);
        settings2.setValue(QStringLiteral("render/capSpacingFraction"), 5.0); // beyond the range
    }
    QCOMPARE(loadRenderChoices(QSettings(iniPath(), QSettings::IniFormat)).capSpacingFraction,
             fallback.capSpacingFraction);
}

// The panel shows the choices it is given and reports them back (plane normals within
// [−1, 1] come back exactly; the spacing as a percentage with one decimal).
void TestInspectSettings::renderPanelShowsWhatItIsGiven()
{
    RenderPanel panel;
    Bounds bounds;
    bounds.extend(glm::dvec3(-2.0, -1.0, -1.0));
    bounds.extend(glm::dvec3(2.0, 1.0, 1.0));
    panel.setSceneInfo(bounds, true, QString());
    RenderChoices given = unusualChoices();
    for (int i = 0; i < kMaxClipPlanes; ++i) // the editor's fields hold 3 and 4 decimals
        given.trim.clipPlane(i) = ClipPlane{i % 2 == 0, {i == 1 ? -1.0 : 0.5, 0.25, -0.125}, -0.25 * i};
    panel.setRenderChoices(given);
    const RenderChoices shown = panel.renderChoices();
    QVERIFY(sameClipSet(shown.trim.clipSet(), given.trim.clipSet()));
    QCOMPARE(shown.trim.cap.enabled, true);
    QCOMPARE(shown.trim.cap.pattern, CapPattern::Solid);
    QCOMPARE(shown.capSpacingFraction, 0.125);
    QVERIFY(std::abs(shown.trim.cap.spacing - 0.125 * bounds.radius()) < 1e-12); // world units of this scene
    QCOMPARE(shown.trim.highlight, given.trim.highlight);
}

void TestInspectSettings::boxNoneAndRowsEditTheSet()
{
    ClipSetEditor editor;
    Bounds bounds;
    bounds.extend(glm::dvec3(-1.0, -2.0, -3.0));
    bounds.extend(glm::dvec3(1.0, 2.0, 3.0));
    editor.setSceneBounds(bounds);
    QSignalSpy changed(&editor, &ClipSetEditor::clipSetChanged);
    QTest::mouseClick(editor.findChild<QPushButton*>(QStringLiteral("clipBoxButton")), Qt::LeftButton);
    QCOMPARE(changed.count(), 1);
    const ClipSet box = editor.clipSet();
    QCOMPARE(box.enabledCount(), 6);
    // Every plane keeps the whole scene and a point just outside each face is cut.
    const double margin = ClipSetEditor::kBoxMargin * glm::length(bounds.max - bounds.min);
    QVERIFY(box.keeps(bounds.min) && box.keeps(bounds.max));
    QVERIFY(!box.keeps(bounds.max + glm::dvec3(2.0 * margin, 0.0, 0.0)));
    QVERIFY(!box.keeps(bounds.min - glm::dvec3(0.0, 0.0, 2.0 * margin)));
    QCOMPARE(editor.selectedPlane(), 0);
    const ClipPlane edited = editor.planeEditor()->plane(); // its offset field has 4 decimals
    QVERIFY(edited.enabled && edited.normal == box.planes[0].normal);
    QVERIFY(std::abs(edited.offset - box.planes[0].offset) <= 0.5e-4);

    // Unticking row 3 disables plane 3 only; the editor (on plane 1) is unchanged.
    auto* row3 = editor.findChild<QCheckBox*>(QStringLiteral("clipPlaneEnabled2"));
    QTest::mouseClick(row3, Qt::LeftButton, {}, QPoint(6, row3->height() / 2)); // on the indicator
    QCOMPARE(changed.count(), 2);
    QVERIFY(!editor.clipSet().planes[2].enabled);
    QCOMPARE(editor.clipSet().enabledCount(), 5);
    editor.selectPlane(2);
    QVERIFY(!editor.planeEditor()->isChecked());
    QCOMPARE(editor.planeEditor()->title(), QStringLiteral("Plane 3"));

    QTest::mouseClick(editor.findChild<QPushButton*>(QStringLiteral("clipNoneButton")), Qt::LeftButton);
    QCOMPARE(editor.clipSet().enabledCount(), 0);
    QCOMPARE(editor.clipSet().planes[4].normal, box.planes[4].normal); // planes kept, only disabled
}

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen"); // widgets without any window system
    QApplication app(argc, argv);
    TestInspectSettings test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_inspect_settings.moc"
