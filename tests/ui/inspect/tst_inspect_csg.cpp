// The Scene panel as a user drives it: CSG expressions built with the buttons and typed
// into the field (validated at every keystroke), undone with Ctrl+Z, and a scene grown
// object by object with Add Object from files the test writes. Every frame is compared
// with the exact CPU reference for its own scene, camera, size and settings.
#include "ui/inspect/inspect_workspace.h"
#include "inspect_window.h"
#include "test_paths.h"

#include "ui/inspect/csg_expression_field.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/object_transform_form.h"
#include "ui/inspect/scene_panel.h"

#include "core/scene/shape_generators.h"
#include "core/trim/csg_expression.h"

#include <QItemSelectionModel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

namespace {

const QString kTrio = QStringLiteral("demo:csg-trio");

CsgExpression parsed(const char* text)
{
    std::string error;
    const std::optional<CsgExpression> expression = parseCsgExpression(text, &error);
    if (!expression)
        qFatal("test expression %s: %s", text, error.c_str());
    return *expression;
}

/// Selects exactly `rows` of the panel's table, the first one current (as clicking it and
/// Ctrl-clicking the others does).
void selectRows(ScenePanel& panel, std::initializer_list<int> rows)
{
    QTableWidget* table = panel.objectTable();
    table->clearSelection();
    bool first = true;
    for (const int row : rows) {
        const auto flags = QItemSelectionModel::Select | QItemSelectionModel::Rows;
        if (first)
            table->selectionModel()->setCurrentIndex(table->model()->index(row, ScenePanel::NameColumn), flags);
        else
            table->selectionModel()->select(table->model()->index(row, ScenePanel::NameColumn), flags);
        first = false;
    }
}

void typeExpression(QLineEdit* edit, const QString& text)
{
    revealed(edit)->setFocus();
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(edit, text);
}

} // namespace

class TestInspectCsg : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void builtAndTypedExpressionsMatchTheReference();
    void addObjectGrowsTheSceneForCsg();

private:
    QTemporaryDir m_dir;
};

void TestInspectCsg::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

// Difference built from the selection, then "0 | (1 & 2)" typed key by key: the frame
// follows each valid text, an invalid one shows the parser's message and keeps the last
// valid expression, and Ctrl+Z undoes the typed expression as one step.
void TestInspectCsg::builtAndTypedExpressionsMatchTheReference()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("built.ini")), kTrio);
    ScenePanel* panel = window->inspectWorkspace()->panel();
    QCOMPARE(panel->objectTable()->rowCount(), 3);
    const TrimImage plain = window->viewport()->readTrimImage();
    const ReferenceResult plainReference = referenceOfLastFrame(*window);

    selectRows(*panel, {0, 1});
    auto* difference = child<QPushButton>(window.get(), "csgDifferenceButton");
    QVERIFY(difference && difference->isEnabled());
    // The button says which object the others are taken from: the current row.
    selectRows(*panel, {1, 0});
    QCOMPARE(panel->currentObject(), 1);
    QCOMPARE(difference->text(), QStringLiteral("Difference: 1 − others"));
    selectRows(*panel, {0, 1});
    QCOMPARE(panel->currentObject(), 0);
    QCOMPARE(difference->text(), QStringLiteral("Difference: 0 − others"));
    QTest::mouseClick(revealed(difference), Qt::LeftButton);
    QCOMPARE(window->inspectWorkspace()->scene()->csg().expression, parsed("0 - 1"));
    QCOMPARE(panel->csgField()->lineEdit()->text(), QStringLiteral("0 - 1"));
    QCOMPARE(panel->objectTable()->item(2, ScenePanel::InCsgColumn)->text(), QString()); // the ring is not shown
    QVERIFY(!panel->objectTable()->item(1, ScenePanel::InCsgColumn)->text().isEmpty());
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.csg.expression == parsed("0 - 1"); }));
    auto failure = inspectDisagreement(*window, QStringLiteral("csg-difference"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    // The scenario discriminates: CSG changes a good part of the picture.
    QVERIFY(changedPixels(referenceOfLastFrame(*window).trim, plainReference.trim) > 200);
    QVERIFY(changedPixels(window->viewport()->readTrimImage(), plain) > 200);

    QLineEdit* edit = panel->csgField()->lineEdit();
    typeExpression(edit, QStringLiteral("0 | (1 &"));
    QVERIFY(!panel->csgField()->errorText().isEmpty());                       // the parser's message, shown at once
    QCOMPARE(window->viewport()->trimSettings().csg.expression, parsed("0")); // the last valid text: "0"
    QTest::keyClicks(edit, QStringLiteral(" 7)"));
    QVERIFY2(panel->csgField()->errorText().contains(QStringLiteral("7")), qPrintable(panel->csgField()->errorText()));
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClick(edit, Qt::Key_Backspace);
    QTest::keyClicks(edit, QStringLiteral("2)"));
    QTest::keyClick(edit, Qt::Key_Return);
    QCOMPARE(panel->csgField()->errorText(), QString());
    const CsgExpression nested = parsed("0 | (1 & 2)");
    QCOMPARE(window->inspectWorkspace()->scene()->csg().expression, nested);
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return f.settings.csg.expression == nested; }));
    failure = inspectDisagreement(*window, QStringLiteral("csg-nested"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
    const QString shot = QString::fromStdString((outputDir() / "scene-panel.png").string());
    QVERIFY(window->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));

    // One undo step for the whole typed expression, back to the built difference.
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(window->inspectWorkspace()->scene()->csg().expression, parsed("0 - 1"));
    QCOMPARE(edit->text(), QStringLiteral("0 - 1"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return f.settings.csg.expression == parsed("0 - 1"); }));
    QTest::keyClick(window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier); // redo
    QCOMPARE(window->inspectWorkspace()->scene()->csg().expression, nested);
}

// A mesh opened from a file, then two more added with Add Object (off the UI thread):
// the camera stays, the design session of the single mesh ends (its transform becomes
// editable), and a CSG over the grown scene agrees with the reference.
void TestInspectCsg::addObjectGrowsTheSceneForCsg()
{
    const QString first = m_dir.filePath(QStringLiteral("first.obj"));
    const QString second = m_dir.filePath(QStringLiteral("second.obj"));
    const QString third = m_dir.filePath(QStringLiteral("third.obj"));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 3), first));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.7, 0.2, 0.3), 0.6, 3), second));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(-0.6, -0.1, 0.2), 0.5, 3), third));
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("added.ini")), first);
    QVERIFY(!window->inspectWorkspace()->panel()->transformForm()->isEnabled()); // the single mesh is designed
    const Camera before = window->viewport()->camera();

    QSignalSpy added(window.get(), &MainWindow::objectAdded);
    window->inspectWorkspace()->addObject(second);
    QVERIFY(added.wait(kInspectWaitMs));
    window->inspectWorkspace()->addObject(third);
    QVERIFY(added.wait(kInspectWaitMs));
    QCOMPARE(window->scene()->scene.objects.size(), std::size_t(3));
    QCOMPARE(window->scene()->source, first.toStdString()); // still the scene opened
    QCOMPARE(window->inspectWorkspace()->panel()->objectTable()->rowCount(), 3);
    QCOMPARE(window->inspectWorkspace()->panel()->objectTable()->item(2, ScenePanel::NameColumn)->text(),
             QStringLiteral("third.obj"));
    QCOMPARE(window->inspectWorkspace()->panel()->currentObject(), 2);
    QVERIFY(window->inspectWorkspace()->panel()->transformForm()->isEnabled());
    const Camera after = window->viewport()->camera();
    QCOMPARE(after.eye, before.eye);
    QCOMPARE(after.target, before.target);

    typeExpression(window->inspectWorkspace()->panel()->csgField()->lineEdit(), QStringLiteral("(0 | 2) - 1"));
    QTest::keyClick(window->inspectWorkspace()->panel()->csgField()->lineEdit(), Qt::Key_Return);
    const CsgExpression expression = parsed("(0 | 2) - 1");
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) {
        return f.settings.csg.expression == expression && f.scene->objects.size() == 3;
    }));
    const auto failure = inspectDisagreement(*window, QStringLiteral("added-objects-csg"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

QTEST_MAIN(TestInspectCsg)
#include "tst_inspect_csg.moc"
