// The Scene panel's model without widgets or OpenGL: InspectScene's transform and CSG
// edits (each replacing the scene value, undoable, merged as documented), Add Object's
// object limit, and the expression field's validation against the scene's objects.
#include "ui/inspect/csg_expression_field.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/set_object_transform_command.h"

#include "core/catalog/demo_scenes.h"
#include "core/scene/shape_generators.h"

#include <QApplication>
#include <QSignalSpy>
#include <QUndoCommand>
#include <QUndoStack>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

std::shared_ptr<const LoadedScene> trio()
{
    auto loaded = std::make_shared<LoadedScene>();
    loaded->scene = *makeDemoScene("csg-trio");
    loaded->source = "demo:csg-trio";
    loaded->displayName = "csg-trio";
    loaded->reports.resize(loaded->scene.objects.size());
    return loaded;
}

CsgSettings withExpression(const char* text)
{
    std::string error;
    const std::optional<CsgExpression> expression = parseCsgExpression(text, &error);
    if (!expression)
        qFatal("test expression %s: %s", text, error.c_str());
    CsgSettings csg;
    csg.expression = *expression;
    return csg;
}

} // namespace

class TestInspectScene : public QObject {
    Q_OBJECT
private slots:
    void transformEditsReplaceTheSceneAndUndo();
    void stepsOfOneComponentMerge();
    void typedExpressionsMergeUntilTypingEnds();
    void addingObjectsRespectsTheLimit();
    void expressionTextIsCheckedAgainstTheScene();
};

void TestInspectScene::transformEditsReplaceTheSceneAndUndo()
{
    InspectScene inspect;
    inspect.reset(trio());
    const std::shared_ptr<const LoadedScene> original = inspect.scene();
    QCOMPARE(inspect.objectCount(), 3);
    QVERIFY(inspect.transform(1) && inspect.transform(1)->isIdentity());
    QSignalSpy moved(&inspect, &InspectScene::transformChanged);

    ObjectTransform transform;
    transform.translation = {0.0, 0.5, 0.0};
    inspect.editTransform(1, transform);
    QCOMPARE(moved.count(), 1);
    QCOMPARE(moved.front().front().toInt(), 1);
    QVERIFY(inspect.scene() != original);                              // a new value ...
    QCOMPARE(original->scene.objects[1].modelMatrix, glm::dmat4(1.0)); // ... the old one untouched
    QCOMPARE(inspect.scene()->scene.objects[1].modelMatrix, transform.modelMatrix());
    QCOMPARE(inspect.scene()->scene.objects[1].mesh.triangles, original->scene.objects[1].mesh.triangles);

    inspect.editTransform(1, transform); // no change: nothing recorded
    QCOMPARE(inspect.undoStack()->count(), 1);
    inspect.editTransform(7, transform); // no such object: ignored
    QCOMPARE(inspect.undoStack()->count(), 1);

    inspect.undoStack()->undo();
    QCOMPARE(inspect.scene()->scene.objects[1].modelMatrix, glm::dmat4(1.0));
    QVERIFY(inspect.transform(1)->isIdentity());
    inspect.reset(trio()); // a new scene: a clean stack
    QCOMPARE(inspect.undoStack()->count(), 0);
}

void TestInspectScene::stepsOfOneComponentMerge()
{
    InspectScene inspect;
    inspect.reset(trio());
    ObjectTransform t;
    for (int step = 1; step <= 3; ++step) { // three steps of rotation about y
        t.rotationDegrees.y = 5.0 * step;
        inspect.editTransform(2, t);
    }
    QCOMPARE(inspect.undoStack()->count(), 1);
    t.scale = 2.0; // another component: a new step
    inspect.editTransform(2, t);
    QCOMPARE(inspect.undoStack()->count(), 2);
    t.scale = 1.0;
    inspect.editTransform(0, t); // another object: a new step, though the same component
    QCOMPARE(inspect.undoStack()->count(), 3);
    inspect.undoStack()->undo();
    inspect.undoStack()->undo();
    QCOMPARE(inspect.transform(2)->rotationDegrees.y, 15.0);
    inspect.undoStack()->undo();
    QVERIFY(inspect.transform(2)->isIdentity());

    ObjectTransform a;
    ObjectTransform b = a;
    b.translation.z = 1.0;
    QCOMPARE(changedTransformComponent(a, b), 2);
    b.scale = 3.0;
    QCOMPARE(changedTransformComponent(a, b), -1);
    QCOMPARE(changedTransformComponent(a, a), -1);
}

void TestInspectScene::typedExpressionsMergeUntilTypingEnds()
{
    InspectScene inspect;
    inspect.reset(trio());
    QSignalSpy changed(&inspect, &InspectScene::csgChanged);
    inspect.editCsg(withExpression("0"), QStringLiteral("typing"), true);
    inspect.editCsg(withExpression("0 | 1"), QStringLiteral("typing"), true);
    QCOMPARE(inspect.undoStack()->count(), 1);
    QCOMPARE(changed.count(), 2);
    inspect.endTyping();
    inspect.editCsg(withExpression("0 - 2"), QStringLiteral("typing again"), true);
    QCOMPARE(inspect.undoStack()->count(), 2);
    CsgSettings rule = inspect.csg();
    rule.objectRules[1] = StaticRule::Parity;
    inspect.editCsg(rule, QStringLiteral("rule")); // not typed: never merges
    inspect.editCsg(rule, QStringLiteral("rule")); // unchanged: not recorded
    QCOMPARE(inspect.undoStack()->count(), 3);
    inspect.undoStack()->undo();
    inspect.undoStack()->undo();
    QCOMPARE(inspect.csg(), withExpression("0 | 1"));
    inspect.undoStack()->undo();
    QVERIFY(!inspect.csg().enabled());

    // '&' is no mnemonic in the Edit menu: doubled in the action text only.
    inspect.editCsg(withExpression("0 & 1"), QStringLiteral("CSG 0 & 1"));
    const QUndoCommand* last = inspect.undoStack()->command(inspect.undoStack()->index() - 1);
    QCOMPARE(last->text(), QStringLiteral("CSG 0 & 1"));
    QCOMPARE(last->actionText(), QStringLiteral("CSG 0 && 1"));
}

void TestInspectScene::addingObjectsRespectsTheLimit()
{
    InspectScene inspect;
    LoadedScene ball;
    ball.scene.objects.push_back({"ball", makeIcosphere(glm::dvec3(0.0), 0.5, 1), glm::dmat4(1.0)});
    ball.reports.resize(1);
    QString error;
    QVERIFY(!inspect.appendObjects(ball, &error)); // no scene yet
    QVERIFY(!error.isEmpty());

    inspect.reset(trio());
    inspect.editCsg(withExpression("0 - 1"), QStringLiteral("csg"));
    QSignalSpy replaced(&inspect, &InspectScene::sceneReplaced);
    QVERIFY(inspect.appendObjects(ball, &error));
    QCOMPARE(replaced.count(), 1);
    QCOMPARE(inspect.objectCount(), 4);
    QCOMPARE(inspect.scene()->reports.size(), std::size_t(4));
    QCOMPARE(inspect.scene()->scene.objects[3].name, std::string("ball"));
    QCOMPARE(inspect.csg(), withExpression("0 - 1")); // kept: ids do not change
    QCOMPARE(inspect.undoStack()->count(), 1);

    LoadedScene many;
    for (std::size_t i = 0; i < Scene::maxObjects - 3; ++i)
        many.scene.objects.push_back(ball.scene.objects.front());
    QVERIFY(!inspect.appendObjects(many, &error)); // 4 + 29 > 32
    QVERIFY2(error.contains(QString::number(Scene::maxObjects)), qPrintable(error));
    QCOMPARE(inspect.objectCount(), 4);
}

void TestInspectScene::expressionTextIsCheckedAgainstTheScene()
{
    QString error;
    QVERIFY(csgExpressionForScene(QStringLiteral("  "), 3, &error)->empty()); // blank: no CSG
    QCOMPARE(*csgExpressionForScene(QStringLiteral("0 | (1 & 2)"), 3, &error),
             CsgExpression::combine(CsgOperation::Union,
                                    {CsgExpression::operand(0),
                                     CsgExpression::combine(CsgOperation::Intersection,
                                                            {CsgExpression::operand(1), CsgExpression::operand(2)})}));
    QVERIFY(!csgExpressionForScene(QStringLiteral("0 | 3"), 3, &error));
    QVERIFY2(error.contains(QStringLiteral("Object 3")) && error.contains(QStringLiteral("0 to 2")), qPrintable(error));
    error.clear();
    QVERIFY(!csgExpressionForScene(QStringLiteral("0 | (1"), 3, &error));
    QVERIFY(!error.isEmpty()); // the parser's message
}

int main(int argc, char** argv)
{
    if (qEnvironmentVariableIsEmpty("DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen"); // no window is shown
    QApplication app(argc, argv);
    TestInspectScene test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_inspect_scene.moc"
