// Each file opened is a document of its own (ui/common/document.h): its view settings, its
// modified state and its title. These are what a newcomer met when one file's state leaked
// into the next — a cut that emptied the next mesh, a design's dynamic rules greying out
// a static mesh's caps, an added object hidden behind the first one's clipping box, a
// replayed design lost without a prompt, a reopened project shown under another
// classification, a title that ignored scene projects, a cap pattern that kept the spacing
// of an object before it was scaled. Each is driven through the real window.
#include "inspect_window.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "plain_obj.h"
#include "test_paths.h"

#include "ui/design/design_session.h"
#include "ui/design/brush_tool.h"
#include "ui/design/design_workspace.h"
#include "ui/design/history_exports.h"
#include "ui/design/project_files.h"
#include "ui/design/session_recovery.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/inspect_workspace.h"
#include "ui/inspect/scene_panel.h"
#include "ui/inspect/csg_expression_field.h"
#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_workspace.h"

#include "render/shown_content.h"
#include "ui/viewport/viewport_widget.h"

#include "core/scene/shape_generators.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

namespace {

const QString kTrio = QStringLiteral("demo:csg-trio");
const QString kSphere = QStringLiteral("demo:sphere");

/// Clicks a check box on its indicator (a click beside its text could miss it).
void clickBox(QAbstractButton* button)
{
    QTest::mouseClick(revealed(button), Qt::LeftButton, {}, QPoint(6, button->height() / 2));
}

void typeValue(QDoubleSpinBox* spin, const QString& text)
{
    revealed(spin)->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Return);
}

/// Pixels of the last frame that show object `object`.
int pixelsOf(ui::MainWindow& window, int object)
{
    int count = 0;
    for (const TrimPixel& pixel : window.viewport()->readTrimImage().pixels)
        count += pixel.objectId == object ? 1 : 0;
    return count;
}

/// Opens `source` and waits until it is shown with a frame of its own.
bool openAndWait(ui::MainWindow& window, const QString& source)
{
    window.openSource(source);
    return QTest::qWaitFor(
        [&] {
            const auto& frame = window.viewport()->lastFrame();
            return !window.isLoading() && window.scene() && window.scene()->source == source.toStdString() && frame &&
                   frame->scene && frame->scene.get() == &window.scene()->scene;
        },
        kInspectWaitMs);
}

/// Whether the view classifies by the dynamic rules (the shown content holds a chain).
bool dynamicRulesShown(ui::MainWindow& window)
{
    return window.viewport()->content()->chain() != nullptr;
}

/// The classification combo box of the Render panel: 0 static rule, 1 dynamic rules.
QComboBox* classificationBox(ui::MainWindow& window)
{
    return child<QComboBox>(&window, "classificationComboBox");
}

void chooseClassification(ui::MainWindow& window, int index)
{
    QComboBox* box = revealed(classificationBox(window));
    box->setFocus();
    while (box->currentIndex() < index)
        QTest::keyClick(box, Qt::Key_Down);
    while (box->currentIndex() > index)
        QTest::keyClick(box, Qt::Key_Up);
}

/// Replays `script` on the design shown and waits for its frames.
bool replayAndWait(ui::MainWindow& window, const QString& script)
{
    QSignalSpy replayed(window.designWorkspace()->historyExports(), &HistoryExports::replayed);
    window.designWorkspace()->historyExports()->replay(script);
    return replayed.wait(kInspectWaitMs) && window.designWorkspace()->session() &&
           window.designWorkspace()->session()->timeline().frameCount() > 1;
}

QString scriptPath()
{
    return QString::fromStdString(testDataPath("scripts/fig8_7_extended_tip.json").string());
}

} // namespace

class TestDocumentState : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void aCutDoesNotFollowToTheNextFile();
    void aStaticMeshAfterADesignIsStatic();
    void anAddedObjectIsInsideTheClippingBox();
    void aReplayedDesignIsModified();
    void aReopenedProjectKeepsItsClassification();
    void theTitleFollowsSceneProjects();
    void theCapSpacingFollowsAScaledObject();
    void theBrushLeavesTheViewWithTheDesign();

private:
    [[nodiscard]] QString meshFile(const char* name, const glm::dvec3& centre, double radius);
    QTemporaryDir m_dir;
};

void TestDocumentState::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

QString TestDocumentState::meshFile(const char* name, const glm::dvec3& centre, double radius)
{
    const QString path = m_dir.filePath(QString::fromLatin1(name));
    if (!writePlainObj(makeIcosphere(centre, radius, 2), path))
        qWarning("cannot write %s", qPrintable(path));
    return path;
}

// Cut a mesh at the origin to x <= 0, then open one that lies at x from 0.21 to 0.59 (as
// the samba animation does): the new file starts uncut, and shows its mesh.
void TestDocumentState::aCutDoesNotFollowToTheNextFile()
{
    const QString first = meshFile("centred.obj", {0.0, 0.0, 0.0}, 1.0);
    const QString second = meshFile("off-centre.obj", {0.4, 0.0, 0.0}, 0.19);
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("cut.ini")), first);
    clickBox(child<QCheckBox>(window.get(), "clipPlaneEnabled0"));
    QTest::mouseClick(revealed(child<QToolButton>(window.get(), "clipPreset-X")), Qt::LeftButton);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) {
        const ClipPlane plane = f.settings.clip;
        return plane.enabled && plane.normal.x < 0.0;
    }));
    QVERIFY(pixelsOf(*window, 0) > 0);

    QVERIFY(openAndWait(*window, second));
    const ViewportFrame frame = *window->viewport()->lastFrame();
    QCOMPARE(frame.settings.clipSet().enabledCount(), 0);
    QVERIFY(!child<QCheckBox>(window.get(), "clipPlaneEnabled0")->isChecked());
    QVERIFY2(pixelsOf(*window, 0) > 100, "the second mesh is not shown");
    QVERIFY(frame.stats.counts.fragmentsInSpan > 0);
}

// A design under the dynamic rules, then a plain mesh: the mesh is a new document under
// the static rule, with capping available.
void TestDocumentState::aStaticMeshAfterADesignIsStatic()
{
    const QString mesh = meshFile("plain.obj", {0.0, 0.0, 0.0}, 1.0);
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("classification.ini")), kSphere);
    chooseClassification(*window, 1);
    QVERIFY(QTest::qWaitFor([&] { return dynamicRulesShown(*window); }, kInspectWaitMs));
    QVERIFY(!child<QCheckBox>(window.get(), "capCheckBox")->isEnabled());

    QVERIFY(openAndWait(*window, mesh));
    QCOMPARE(classificationBox(*window)->currentIndex(), 0);
    QVERIFY(!dynamicRulesShown(*window));
    QVERIFY(child<QCheckBox>(window.get(), "capCheckBox")->isEnabled());
}

// A box of clipping planes around the first object; an object added beside it is inside
// the grown scene's box and shows.
void TestDocumentState::anAddedObjectIsInsideTheClippingBox()
{
    const QString first = meshFile("first.obj", {0.0, 0.0, 0.0}, 1.0);
    const QString added = meshFile("added.obj", {2.5, 0.0, 0.0}, 0.8);
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("box.ini")), first);
    QTest::mouseClick(revealed(child<QPushButton>(window.get(), "clipBoxButton")), Qt::LeftButton);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.clipSet().enabledCount() == 6; }));

    QSignalSpy appended(window->inspectWorkspace(), &InspectWorkspace::objectsAppended);
    window->inspectWorkspace()->addObject(added);
    QVERIFY(appended.wait(kInspectWaitMs));
    window->viewport()->fitToView();
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.scene->objects.size() == 2; }));
    QTest::qWait(50);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.clipSet().enabledCount() == 6; }));
    QVERIFY2(pixelsOf(*window, 1) > 50, "the added object is clipped away");
    QVERIFY(pixelsOf(*window, 0) > 50);
}

// A design made by replaying a stroke script exists in no file: it is modified (the
// title's '*'), autosave covers it, and opening another file asks first.
void TestDocumentState::aReplayedDesignIsModified()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("replay.ini")), kSphere);
    QVERIFY(!window->isWindowModified());
    QVERIFY(replayAndWait(*window, scriptPath()));
    QVERIFY(window->isWindowModified());
    QVERIFY(window->designWorkspace()->sessionRecovery()->autosave().saveNow());

    const int frames = window->designWorkspace()->session()->timeline().frameCount();
    {
        MessageBoxAnswerer cancel(QMessageBox::Cancel);
        window->openSource(QStringLiteral("demo:pushed-sphere"));
        QTRY_VERIFY_WITH_TIMEOUT(!cancel.names().isEmpty(), kInspectWaitMs);
        QCOMPARE(cancel.names().front(), QStringLiteral("unsavedHistoryBox"));
    }
    QTest::qWait(100);
    QCOMPARE(window->scene()->source, kSphere.toStdString());
    QCOMPARE(window->designWorkspace()->session()->timeline().frameCount(), frames);
    window->designWorkspace()->sessionRecovery()->autosave().clear();
}

// A design saved under the dynamic rules opens under them again, whatever the document
// before it was classified with.
void TestDocumentState::aReopenedProjectKeepsItsClassification()
{
    const QString project = m_dir.filePath(QStringLiteral("dynamic.trimlab"));
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("reopen.ini")), kSphere);
    QVERIFY(replayAndWait(*window, scriptPath()));
    chooseClassification(*window, 1);
    QVERIFY(QTest::qWaitFor([&] { return dynamicRulesShown(*window); }, kInspectWaitMs));
    QString error;
    QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(project, &error), qPrintable(error));

    QVERIFY(openAndWait(*window, QStringLiteral("demo:pushed-sphere")));
    chooseClassification(*window, 0);
    QVERIFY(QTest::qWaitFor([&] { return !dynamicRulesShown(*window); }, kInspectWaitMs));

    window->openSource(project);
    QVERIFY(QTest::qWaitFor(
        [&] { return !window->isLoading() && window->scene() && window->scene()->source == project.toStdString(); },
        kInspectWaitMs));
    QCOMPARE(classificationBox(*window)->currentIndex(), 1);
    QVERIFY(QTest::qWaitFor([&] { return dynamicRulesShown(*window); }, kInspectWaitMs));
}

// A scene of three objects: a CSG edit marks the title, Save Project names the file and
// clears the mark, adding an object marks it again.
void TestDocumentState::theTitleFollowsSceneProjects()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("title.ini")), kTrio);
    QVERIFY2(window->windowTitle().contains(QStringLiteral("csg-trio")), qPrintable(window->windowTitle()));
    QVERIFY(!window->isWindowModified());

    QLineEdit* csg = window->inspectWorkspace()->panel()->csgField()->lineEdit();
    revealed(csg)->setFocus();
    QTest::keyClicks(csg, QStringLiteral("0 - 1"));
    QTest::keyClick(csg, Qt::Key_Return);
    QTRY_VERIFY_WITH_TIMEOUT(window->isWindowModified(), kInspectWaitMs);

    const QString project = m_dir.filePath(QStringLiteral("trio.trimlab"));
    QString error;
    QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(project, &error), qPrintable(error));
    QVERIFY2(window->windowTitle().startsWith(QStringLiteral("trio.trimlab")), qPrintable(window->windowTitle()));
    QVERIFY(!window->isWindowModified());

    QSignalSpy appended(window->inspectWorkspace(), &InspectWorkspace::objectsAppended);
    window->inspectWorkspace()->addObject(meshFile("fourth.obj", {0.0, 2.0, 0.0}, 0.3));
    QVERIFY(appended.wait(kInspectWaitMs));
    QVERIFY(window->isWindowModified());
}

// Caps on a cut through the trio; the ball scaled up widens the scene: the pattern's
// spacing is the same fraction of the new radius.
void TestDocumentState::theCapSpacingFollowsAScaledObject()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("spacing.ini")), kTrio);
    clickBox(child<QCheckBox>(window.get(), "clipPlaneEnabled0"));
    clickBox(child<QCheckBox>(window.get(), "capCheckBox"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.capping(); }));
    const double fraction = window->renderWorkspace()->panel()->renderChoices().capSpacingFraction;
    const double before = window->viewport()->lastFrame()->settings.cap.spacing;

    window->inspectWorkspace()->panel()->setCurrentObject(1);
    typeValue(child<QDoubleSpinBox>(window.get(), "uniformScale"), QStringLiteral("3"));
    QVERIFY(QTest::qWaitFor([&] { return window->inspectWorkspace()->scene()->transform(1)->scale == 3.0; },
                            kInspectWaitMs));
    const double radius = window->scene()->scene.worldBounds().radius();
    QVERIFY(std::abs(fraction * radius - before) > 1e-3); // the scene did grow
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) {
        return f.scene->objects[1].modelMatrix[0][0] == 3.0 &&
               std::abs(f.settings.cap.spacing - fraction * radius) < 1e-9;
    }));
}

// The brush belongs to a design: opening an animation with the brush on gives the mouse
// (and the view's tooltip, one line per gesture) back to the camera; the next design gets
// the brush again, as the Brush button still says.
void TestDocumentState::theBrushLeavesTheViewWithTheDesign()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("brush.ini")), kSphere);
    QVERIFY(window->designWorkspace()->session());
    window->designWorkspace()->brushAction()->setChecked(true);
    ViewportWidget* viewport = window->viewport();
    QCOMPARE(viewport->tool(), static_cast<ViewportTool*>(window->designWorkspace()->brushTool()));

    QSignalSpy loaded(window.get(), &ui::MainWindow::animationLoaded);
    window->openAnimation(QString::fromStdString(testDataPath("animations/folding_box").string()));
    QVERIFY(QTest::qWaitFor([&] { return !loaded.isEmpty() && !window->isLoading(); }, kInspectWaitMs));
    QVERIFY(!window->designWorkspace()->session());
    QCOMPARE(viewport->tool(), nullptr);
    QVERIFY2(viewport->toolTip().contains(QStringLiteral("orbit")) && viewport->toolTip().contains(QLatin1Char('\n')),
             qPrintable(viewport->toolTip()));
    for (const QString& line : viewport->toolTip().split(QLatin1Char('\n')))
        QVERIFY2(line.size() <= 80, qPrintable(line));

    QVERIFY(openAndWait(*window, kSphere));
    QVERIFY(window->designWorkspace()->session());
    QVERIFY(window->designWorkspace()->brushAction()->isChecked());
    QCOMPARE(viewport->tool(), static_cast<ViewportTool*>(window->designWorkspace()->brushTool()));
}

QTEST_MAIN(TestDocumentState)
#include "tst_document_state.moc"
