// The Scene panel's "Trimmed solid" group in the real window: on screen, it gives the
// volume and surface area of the solid the view shows as the core measures the frame's
// own scene and classification, measured off the UI thread once the view rests; it
// follows a new CSG expression and says why there is no solid when trimming is off. Off,
// it measures nothing, and the choice persists. Behind another dock tab it measures
// nothing either, and it measures once its tab is raised.
#include "inspect_window.h"

#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/inspect_workspace.h"
#include "ui/inspect/scene_panel.h"
#include "ui/inspect/solid_measures_view.h"

#include "core/solid/solid_measures.h"
#include "core/trim/csg_expression.h"

#include <QCheckBox>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <cmath>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

namespace {

constexpr int kMeasureWaitMs = 60000;

SolidMeasuresView* measuresOf(MainWindow& window)
{
    return window.inspectWorkspace()->panel()->solidMeasures();
}

/// The number after `name` in the group's text ("volume 0.123,"); NaN when absent.
double shownNumber(const QString& text, const QString& name)
{
    const QRegularExpressionMatch match = QRegularExpression(name + QStringLiteral(" ([-+0-9.e]+)")).match(text);
    return match.hasMatch() ? match.captured(1).toDouble() : std::nan("");
}

/// Waits for the view to rest with its numbers (or refusal) for the frame shown.
bool waitForMeasures(SolidMeasuresView& view)
{
    return QTest::qWaitFor([&] { return !view.isMeasuring() && !view.text().startsWith(QStringLiteral("Measuring")); },
                           kMeasureWaitMs);
}

/// The text shows the volume and area the core measures for the last frame.
void verifyMatchesTheFrame(MainWindow& window)
{
    const ViewportFrame frame = *window.viewport()->lastFrame();
    const SolidMeasures expected = measureTrimmedSolid(*frame.scene, frame.settings);
    const QString text = measuresOf(window)->text();
    QVERIFY2(std::abs(shownNumber(text, QStringLiteral("volume")) - expected.volume) <= 1e-5 * expected.volume,
             qPrintable(text));
    QVERIFY2(std::abs(shownNumber(text, QStringLiteral("surface area")) - expected.area) <= 1e-5 * expected.area,
             qPrintable(text));
}

} // namespace

class TestInspectSolidMeasures : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void followsTheSolidShown();
    void offMeasuresNothingAndPersists();
    void aHiddenPanelMeasuresNothing();

private:
    QTemporaryDir m_dir;
};

void TestInspectSolidMeasures::initTestCase()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    QVERIFY(m_dir.isValid());
}

void TestInspectSolidMeasures::followsTheSolidShown()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("follow.ini")), QStringLiteral("demo:csg-trio"));
    SolidMeasuresView* view = revealed(measuresOf(*window));
    QVERIFY(view && view->measuresAsShown());
    QVERIFY(waitForMeasures(*view));
    QVERIFY2(view->text().contains(QStringLiteral("volume")), qPrintable(view->text()));
    verifyMatchesTheFrame(*window);
    const double before = shownNumber(view->text(), QStringLiteral("volume"));

    InspectScene* scene = window->inspectWorkspace()->scene();
    CsgSettings csg = scene->csg();
    csg.expression = parseCsgExpression("0 - 1", nullptr).value();
    scene->editCsg(csg, QStringLiteral("test CSG"));
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.settings.csg == csg; }));
    QVERIFY(QTest::qWaitFor([&] { return view->text().contains(QStringLiteral("the CSG 0 - 1")); }, kMeasureWaitMs));
    QVERIFY(waitForMeasures(*view));
    verifyMatchesTheFrame(*window);
    QVERIFY(shownNumber(view->text(), QStringLiteral("volume")) < before);

    QTest::keyClick(revealed(child<QCheckBox>(window.get(), "trimCheckBox")), Qt::Key_Space);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return !f.settings.trimEnabled; }));
    revealed(view);
    QVERIFY2(QTest::qWaitFor([&] { return view->text().contains(QStringLiteral("Trimming is off")); }, kMeasureWaitMs),
             qPrintable(view->text()));
}

void TestInspectSolidMeasures::offMeasuresNothingAndPersists()
{
    const QString ini = m_dir.filePath(QStringLiteral("off.ini"));
    {
        auto window = showInspectWindow(ini, QStringLiteral("demo:csg-trio"));
        SolidMeasuresView* view = revealed(measuresOf(*window));
        QTest::keyClick(revealed(child<QCheckBox>(view, "measureSolidCheck")), Qt::Key_Space);
        QVERIFY(!view->measuresAsShown());
        QVERIFY(!view->isMeasuring());
        window->viewport()->update();
        QTest::qWait(800); // longer than the view's rest
        QVERIFY(!view->isMeasuring());
        QVERIFY2(std::isnan(shownNumber(view->text(), QStringLiteral("volume"))), qPrintable(view->text()));
    }
    auto window = showInspectWindow(ini, QStringLiteral("demo:csg-trio"));
    SolidMeasuresView* view = revealed(measuresOf(*window));
    QVERIFY(!view->measuresAsShown());
    QTest::keyClick(revealed(child<QCheckBox>(view, "measureSolidCheck")), Qt::Key_Space);
    QVERIFY(view->measuresAsShown());
    QVERIFY(waitForMeasures(*view));
    verifyMatchesTheFrame(*window);
}

void TestInspectSolidMeasures::aHiddenPanelMeasuresNothing()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("hidden.ini")), QStringLiteral("demo:csg-trio"));
    SolidMeasuresView* view = measuresOf(*window);
    revealed(child<QCheckBox>(window.get(), "trimCheckBox")); // the Render panel in front
    QVERIFY(view->visibleRegion().isEmpty());
    QTest::qWait(800);
    QVERIFY(!view->isMeasuring());
    QVERIFY2(std::isnan(shownNumber(view->text(), QStringLiteral("volume"))), qPrintable(view->text()));
    revealed(view); // no frame renders: raising the tab is what starts it
    QVERIFY(waitForMeasures(*view));
    verifyMatchesTheFrame(*window);
}

QTEST_MAIN(TestInspectSolidMeasures)
#include "tst_inspect_solid_measures.moc"
