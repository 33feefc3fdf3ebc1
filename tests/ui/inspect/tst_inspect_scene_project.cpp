// A scene of three objects built in the window (a mesh opened, two added with Add Object,
// one moved and turned, a CSG typed, an object's rule chosen) saved with Save Project as
// a scene project, and reopened in another window: the same objects, meshes, placements,
// CSG and rules, the frame agreeing with the exact CPU reference, and Save Project
// writing the same scene back to the file it came from.
#include "ui/common/document.h"
#include "ui/inspect/inspect_workspace.h"
#include "inspect_window.h"
#include "message_box_closer.h"
#include "test_paths.h"

#include "ui/design/design_workspace.h"
#include "ui/design/project_files.h"
#include "ui/inspect/csg_expression_field.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/scene_panel.h"

#include "core/scene/shape_generators.h"
#include "core/timeline/project_file.h"
#include "core/trim/csg_expression.h"

#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <filesystem>

using namespace trimlab;
using namespace trimlab::ui;
using namespace trimlab::test;

class TestInspectSceneProject : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void threeObjectsSaveAndReopenIdentical();
    void anUnsavedAssemblyAsksBeforeItIsReplaced();

private:
    QTemporaryDir m_dir;
};

void TestInspectSceneProject::initTestCase()
{
    TRIMLAB_SKIP_WITHOUT_GL();
    QVERIFY(m_dir.isValid());
}

void TestInspectSceneProject::threeObjectsSaveAndReopenIdentical()
{
    const QString first = m_dir.filePath(QStringLiteral("first.obj"));
    const QString second = m_dir.filePath(QStringLiteral("second.obj"));
    const QString third = m_dir.filePath(QStringLiteral("third.obj"));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 3), first));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.0), 0.6, 3), second));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(-0.6, -0.1, 0.2), 0.5, 3), third));
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("build.ini")), first);
    QSignalSpy added(window.get(), &MainWindow::objectAdded);
    window->inspectWorkspace()->addObject(second);
    QVERIFY(added.wait(kInspectWaitMs));
    window->inspectWorkspace()->addObject(third);
    QVERIFY(added.wait(kInspectWaitMs));

    InspectScene* scene = window->inspectWorkspace()->scene();
    ObjectTransform moved = scene->transform(1).value();
    moved.translation = {0.7, 0.2, 0.3};
    moved.rotationDegrees = {0.0, 30.0, 0.0};
    scene->editTransform(1, moved);
    QLineEdit* csgEdit = revealed(window->inspectWorkspace()->panel()->csgField()->lineEdit());
    csgEdit->setFocus();
    QTest::keyClick(csgEdit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(csgEdit, QStringLiteral("0 | 2 - 1"));
    QTest::keyClick(csgEdit, Qt::Key_Return);
    auto* ruleCombo = revealed(child<QComboBox>(window.get(), "objectRuleCombo2"));
    QVERIFY(ruleCombo);
    ruleCombo->setFocus();
    QTest::keyClick(ruleCombo, Qt::Key_End); // the last rule offered: |w| >= 3
    QCOMPARE(scene->csg().objectRules[2], std::optional<StaticRule>(StaticRule::absAtLeast(3)));
    QCOMPARE(formatCsgExpression(scene->csg().expression), std::string("0 | 2 - 1"));

    ProjectFiles* projects = window->designWorkspace()->projectFiles();
    QVERIFY(projects->canSave()); // no history is shown (several objects): the scene is saved
    const QString path = m_dir.filePath(QStringLiteral("assembly.trimlab"));
    QString error;
    QVERIFY2(projects->saveTo(path, &error), qPrintable(error));
    const std::shared_ptr<const LoadedScene> built = window->scene();
    const CsgSettings builtCsg = scene->csg();

    auto reopened = showInspectWindow(m_dir.filePath(QStringLiteral("reopen.ini")), path);
    const std::shared_ptr<const LoadedScene> loaded = reopened->scene();
    QVERIFY(loaded);
    QCOMPARE(loaded->scene.objects.size(), std::size_t(3));
    for (std::size_t i = 0; i < 3; ++i) {
        const SceneObject& a = built->scene.objects[i];
        const SceneObject& b = loaded->scene.objects[i];
        QCOMPARE(b.name, a.name);
        QCOMPARE(b.modelMatrix, a.modelMatrix);
        QVERIFY(b.mesh.positions == a.mesh.positions);
        QVERIFY(b.mesh.triangles == a.mesh.triangles);
    }
    QVERIFY(reopened->inspectWorkspace()->csg() == builtCsg);
    QCOMPARE(child<QComboBox>(reopened.get(), "objectRuleCombo2")->currentData().toString(), QStringLiteral("|w|>=3"));
    QCOMPARE(reopened->inspectWorkspace()->panel()->csgField()->lineEdit()->text(), QStringLiteral("0 | 2 - 1"));
    QVERIFY(waitForFrame(*reopened, [&](const ViewportFrame& f) {
        return f.settings.csg == builtCsg && f.scene.get() == &loaded->scene;
    }));
    const auto failure = inspectDisagreement(*reopened, QStringLiteral("reopened-scene-project"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    // Save Project writes back to the file the scene came from, without asking.
    QVERIFY(std::filesystem::remove(path.toStdString()));
    QVERIFY(reopened->designWorkspace()->projectFiles()->save());
    const timeline::Project again = timeline::readProject(path.toStdString());
    QVERIFY(again.scene.has_value());
    QVERIFY(*again.scene == (timeline::ProjectScene{built->scene.objects, builtCsg}));
}

// Objects put together exist nowhere else until saved: opening another file asks first
// (Cancel keeps the assembly, Discard lets the file open); once saved, nothing is asked;
// a moved object makes it unsaved again, and so does moving the one object of a mesh.
void TestInspectSceneProject::anUnsavedAssemblyAsksBeforeItIsReplaced()
{
    const QString first = m_dir.filePath(QStringLiteral("a.obj"));
    const QString second = m_dir.filePath(QStringLiteral("b.obj"));
    const QString other = m_dir.filePath(QStringLiteral("other.obj"));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.0), 1.0, 2), first));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.5, 0.0, 0.0), 0.6, 2), second));
    QVERIFY(writePlainObj(makeIcosphere(glm::dvec3(0.0), 0.8, 1), other));
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("ask.ini")), first);
    QSignalSpy added(window.get(), &MainWindow::objectAdded);
    window->inspectWorkspace()->addObject(second);
    QVERIFY(added.wait(kInspectWaitMs));
    InspectScene* scene = window->inspectWorkspace()->scene();
    QVERIFY(window->document()->isModified());

    QSignalSpy loaded(window.get(), &MainWindow::sceneLoaded);
    {
        MessageBoxAnswerer cancel(QMessageBox::Cancel);
        window->openSource(other);
        QCOMPARE(cancel.names(), QStringList{QStringLiteral("unsavedSceneBox")});
        QVERIFY2(cancel.seen().first().contains(QStringLiteral("2 objects")), qPrintable(cancel.seen().first()));
    }
    QVERIFY(!loaded.wait(300));
    QCOMPARE(scene->objectCount(), 2);

    QString error;
    QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(m_dir.filePath(QStringLiteral("ab.trimlab")), &error),
             qPrintable(error));
    QVERIFY(!window->document()->isModified());
    ObjectTransform moved = scene->transform(1).value();
    moved.translation.x += 0.25;
    scene->editTransform(1, moved);
    QVERIFY(window->document()->isModified());
    {
        MessageBoxAnswerer discard(QMessageBox::Discard);
        window->openSource(other);
        QCOMPARE(discard.names(), QStringList{QStringLiteral("unsavedSceneBox")});
    }
    QVERIFY(loaded.count() > 0 || loaded.wait(kInspectWaitMs));
    QCOMPARE(scene->objectCount(), 1);

    // One mesh moved is a change of its document like any other: it is asked about too.
    ObjectTransform nudged = scene->transform(0).value();
    nudged.translation.y += 0.1;
    scene->editTransform(0, nudged);
    QVERIFY(window->document()->isModified());
    MessageBoxAnswerer discardMove(QMessageBox::Discard);
    window->openSource(first);
    QVERIFY(loaded.wait(kInspectWaitMs));
    QCOMPARE(discardMove.seen().size(), 1);
    QVERIFY(!window->document()->isModified());
}

QTEST_MAIN(TestInspectSceneProject)
#include "tst_inspect_scene_project.moc"
