// Object transforms edited in the Scene panel: typed translation and rotation re-render
// the moved object (only its model matrix changes; the camera stays), CSG follows the
// moved solids, spin box steps merge into one undo step, and Ctrl+Z / Ctrl+Shift+Z undo
// and redo the moves. Every frame is compared with the exact CPU reference for its own
// scene (model matrices included), camera, size and settings.
#include "ui/inspect/inspect_workspace.h"
#include "inspect_window.h"

#include "ui/inspect/csg_expression_field.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/object_transform_form.h"
#include "ui/inspect/scene_panel.h"

#include "core/trim/csg_expression.h"

#include <glm/trigonometric.hpp>

#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>

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

/// A pixel (device coordinates) deep inside object `object` of `image`: its 7×7
/// neighbourhood shows that object only (no silhouette or cap nearby). (−1, −1) if none.
QPoint pixelInside(const TrimImage& image, int object)
{
    for (int y = 3; y + 3 < image.height; ++y)
        for (int x = 3; x + 3 < image.width; ++x) {
            bool inside = true;
            for (int dy = -3; dy <= 3 && inside; ++dy)
                for (int dx = -3; dx <= 3 && inside; ++dx)
                    inside = image.at(x + dx, y + dy).objectId == object && !image.at(x + dx, y + dy).isCap();
            if (inside)
                return {x, y};
        }
    return {-1, -1};
}

glm::dvec3 translationOf(const ViewportFrame& frame, int object)
{
    return glm::dvec3(frame.scene->objects[std::size_t(object)].modelMatrix[3]);
}

} // namespace

class TestInspectTransform : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void typedTransformsRerenderAndUndo();
    void ctrlDragMovesTheObjectUnderTheCursor();

private:
    QTemporaryDir m_dir;
};

void TestInspectTransform::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

void TestInspectTransform::typedTransformsRerenderAndUndo()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("transform.ini")), kTrio);
    ScenePanel* panel = window->inspectWorkspace()->panel();
    const Camera camera = window->viewport()->camera();
    const TrimImage before = window->viewport()->readTrimImage();

    // The ball (object 1) 0.6 along x.
    panel->setCurrentObject(1);
    QVERIFY(panel->transformForm()->isEnabled());
    typeValue(child<QDoubleSpinBox>(window.get(), "translateX"), QStringLiteral("0.6"));
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) { return translationOf(f, 1).x == 0.6; }));
    QCOMPARE(window->scene()->scene.objects[1].modelMatrix[3][0], 0.6);
    QCOMPARE(window->scene()->scene.objects[0].modelMatrix, glm::dmat4(1.0)); // the others stay
    QCOMPARE(window->viewport()->camera().eye, camera.eye);
    QVERIFY(changedPixels(window->viewport()->readTrimImage(), before) > 100);
    auto failure = inspectDisagreement(*window, QStringLiteral("moved-ball"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    // The ring (object 2) rotated 40° about z by typing, then two arrow steps of 5°
    // (consecutive edits of one component: one undo step), under a CSG difference.
    panel->setCurrentObject(2);
    auto* rotateZ = child<QDoubleSpinBox>(window.get(), "rotateZ");
    typeValue(rotateZ, QStringLiteral("40"));
    QTest::keyClick(rotateZ, Qt::Key_Up);
    QTest::keyClick(rotateZ, Qt::Key_Up);
    QCOMPARE(window->inspectWorkspace()->scene()->transform(2)->rotationDegrees.z, 50.0);
    QLineEdit* csg = panel->csgField()->lineEdit();
    revealed(csg)->setFocus();
    QTest::keyClicks(csg, QStringLiteral("0 - 2"));
    QTest::keyClick(csg, Qt::Key_Return);
    const glm::dmat4 ring = window->inspectWorkspace()->scene()->transform(2)->modelMatrix();
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) {
        return f.scene->objects[2].modelMatrix == ring && !f.settings.csg.expression.empty();
    }));
    failure = inspectDisagreement(*window, QStringLiteral("rotated-ring-csg"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    // Undo: the CSG, then the rotation (typed and stepped, merged); redo brings it back.
    window->viewport()->setFocus(); // Ctrl+Z in the expression field is the field's own undo
    QCOMPARE(window->inspectWorkspace()->scene()->undoStack()->count(), 3); // move ball, rotate ring, CSG
    for (int i = 0; i < 2; ++i)
        QTest::keyClick(window->viewport(), Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(window->inspectWorkspace()->scene()->transform(2)->rotationDegrees.z, 0.0);
    QVERIFY(window->inspectWorkspace()->scene()->csg().expression.empty());
    QCOMPARE(rotateZ->value(), 0.0);
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) {
        return f.scene->objects[2].modelMatrix == glm::dmat4(1.0) && f.settings.csg.expression.empty();
    }));
    QTest::keyClick(window->viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(window->inspectWorkspace()->scene()->transform(2)->rotationDegrees.z, 50.0);
    QCOMPARE(window->scene()->scene.objects[1].modelMatrix[3][0], 0.6); // never undone
    QVERIFY(waitForFrame(*window, [](const ViewportFrame& f) {
        return std::abs(f.scene->objects[2].modelMatrix[0][1] - std::sin(glm::radians(50.0))) < 1e-12;
    }));
    failure = inspectDisagreement(*window, QStringLiteral("redo-ring"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");
}

// Ctrl + left drag on the ball moves the ball (not the camera) in the view plane, as one
// undo step however many moves the drag has; without Ctrl the same drag orbits.
void TestInspectTransform::ctrlDragMovesTheObjectUnderTheCursor()
{
    auto window = showInspectWindow(m_dir.filePath(QStringLiteral("drag.ini")), kTrio);
    ViewportWidget* viewport = window->viewport();
    QVERIFY(viewport->objectDragEnabled());
    const QPoint device = pixelInside(viewport->readTrimImage(), 1);
    QVERIFY2(device.x() >= 0, "no pixel deep inside the ball");
    const QPoint start = (QPointF(device) / viewport->devicePixelRatio()).toPoint();
    const Camera camera = viewport->camera();
    const int stepsBefore = window->inspectWorkspace()->scene()->undoStack()->count();

    QTest::mousePress(viewport, Qt::LeftButton, Qt::ControlModifier, start);
    QTest::mouseMove(viewport, start + QPoint(6, 0));
    QTest::mouseMove(viewport, start + QPoint(12, -4));
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::ControlModifier, start + QPoint(12, -4));
    QCOMPARE(viewport->camera().eye, camera.eye); // the camera did not orbit
    const glm::dvec3 moved = window->inspectWorkspace()->scene()->transform(1)->translation;
    QVERIFY(glm::length(moved) > 0.0);
    // In the view plane: no component along the view direction (pixel rays at one depth).
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    QVERIFY2(std::abs(glm::dot(moved, forward)) < 0.05 * glm::length(moved),
             qPrintable(QStringLiteral("%1 along the view").arg(glm::dot(moved, forward))));
    QCOMPARE(window->inspectWorkspace()->scene()->undoStack()->count(), stepsBefore + 1);
    QVERIFY(waitForFrame(*window, [&](const ViewportFrame& f) { return translationOf(f, 1) == moved; }));
    const auto failure = inspectDisagreement(*window, QStringLiteral("dragged-ball"));
    QVERIFY2(!failure, failure ? qPrintable(*failure) : "");

    QTest::mousePress(viewport, Qt::LeftButton, {}, start);
    QTest::mouseMove(viewport, start + QPoint(10, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, start + QPoint(10, 0));
    QVERIFY(viewport->camera().eye != camera.eye); // plain left drag orbits
    QCOMPARE(window->inspectWorkspace()->scene()->transform(1)->translation, moved);
}

QTEST_MAIN(TestInspectTransform)
#include "tst_inspect_transform.moc"
