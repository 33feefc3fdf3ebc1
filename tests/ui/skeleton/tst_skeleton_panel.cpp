// The Skeleton panel in the real main window, driven like a user: open a generated closed
// mesh (a three-armed star, tests/core/skeleton/skeleton_shapes.h) written to an OBJ file, press
// Run, and check the rig, the stage views in the viewport, posing with the spin boxes and
// by dragging a bone in the view, Reset pose, the re-selection that keeps the contraction,
// Cancel, the refusal of an open mesh, the exports and the settings. Settings go to INI
// files in a temporary folder, never the user's.
#include "gl_test_context.h"
#include "gltf_validation.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "shown_main_window.h"
#include "plain_obj.h"
#include "skeleton_shapes.h"

#include "ui/common/background_job.h"
#include "ui/common/heat_map_legend.h"
#include "ui/window/main_window.h"
#include "ui/skeleton/skeleton_workspace.h"
#include "ui/design/design_workspace.h"
#include "core/skeleton/rig_measures.h"
#include "core/skeleton/skeleton_json.h"
#include "ui/skeleton/skeleton_overlay.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/viewport/widget_projection.h"
#include "ui/skeleton/skeleton_settings_store.h"
#include "ui/viewport/viewport_widget.h"

#include "render/shown_content.h"

#include <QtTest>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextStream>
#include <QToolButton>
#include <QElapsedTimer>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <set>
#include <utility>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;
using trimlab::test::MessageBoxCloser;

namespace {

constexpr QSize kViewportSize(256, 192);
constexpr int kWaitMs = 30000;
constexpr double kStarCell = 0.07;

template <class SpinBox>
void typeInto(SpinBox* box, double value)
{
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, QString::number(value));
    QTest::keyClick(box, Qt::Key_Return);
}

/// The bones below `bone` (its descendants) and itself.
std::vector<bool> subtreeOf(const SkeletonRig& rig, int bone)
{
    std::vector<bool> in(rig.bones.size(), false);
    in[std::size_t(bone)] = true;
    for (std::size_t b = 0; b < rig.bones.size(); ++b) // parents come first
        if (rig.bones[b].parentBone >= 0 && in[std::size_t(rig.bones[b].parentBone)])
            in[b] = true;
    return in;
}

float boneWeightOf(const BoneWeights& weights, std::size_t v, int bone)
{
    for (std::size_t k = 0; k < kBoneInfluences; ++k)
        if (weights.bones[v][k] == bone)
            return weights.weights[v][k];
    return 0.0f;
}

/// The leaf bone (no bone below it) with the most vertices weighted over 0.5 to it, and
/// that count.
std::pair<int, std::size_t> mostWeightedLeaf(const SkeletonRig& rig, const BoneWeights& weights)
{
    int bone = -1;
    std::size_t most = 0;
    for (std::size_t b = 0; b < rig.bones.size(); ++b) {
        const std::vector<bool> below = subtreeOf(rig, int(b));
        if (std::count(below.begin(), below.end(), true) != 1)
            continue; // not a leaf
        std::size_t count = 0;
        for (std::size_t v = 0; v < weights.bones.size(); ++v)
            count += boneWeightOf(weights, v, int(b)) > 0.5f ? 1 : 0;
        if (count > most) {
            most = count;
            bone = int(b);
        }
    }
    return {bone, most};
}

/// Bone `bone` of the panel's overlay on screen, head and tail (nullopt when either is
/// off the view).
std::optional<std::pair<QPointF, QPointF>> screenBone(const SkeletonPanel& panel, const SkeletonRig& rig, int bone)
{
    const auto points = panel.overlay()->projectedJoints();
    const auto& head = points[std::size_t(rig.bones[std::size_t(bone)].head)];
    const auto& tail = points[std::size_t(rig.bones[std::size_t(bone)].tail)];
    if (!head || !tail)
        return std::nullopt;
    return std::pair{*head, *tail};
}

} // namespace

class TestSkeletonPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void projectionFollowsTheCamera();
    void runStagesPoseAndReset();
    void poseStepsUndoAndRedo();
    void posingFollowsTheDynamicRules();
    void cancelDuringRunChangesNothing();
    void openMeshIsRefusedInThePanel();
    void exportsWriteValidFiles();
    void settingsRoundTrip();
    void runFollowsTheChoicesSolverFolded();

private:
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& settingsName);
    [[nodiscard]] static bool openAndWait(MainWindow& window, const QString& path);
    [[nodiscard]] static bool runAndWait(SkeletonPanel* panel);
    [[nodiscard]] static bool waitForNewFrame(MainWindow& window, const std::function<void()>& action);
    /// The star opened, the Skeleton dock raised, Run done with 20 target nodes.
    [[nodiscard]] std::unique_ptr<MainWindow> extractedStar(const QString& settingsName);

    QTemporaryDir m_dir;
    QString m_star;
    QString m_open;
    std::size_t m_starVertices = 0;
};

void TestSkeletonPanel::initTestCase()
{
    QVERIFY(m_dir.isValid());
    // TRIMLAB_SKELETON_TEST_CELL: a finer star for measuring (e.g. 0.03 ≈ 20k vertices).
    const double cell = qEnvironmentVariableIsSet("TRIMLAB_SKELETON_TEST_CELL")
                            ? qEnvironmentVariable("TRIMLAB_SKELETON_TEST_CELL").toDouble()
                            : kStarCell;
    const TriangleMesh star = test::Star{}.mesh(cell > 0.0 ? cell : kStarCell);
    m_starVertices = star.vertexCount();
    qInfo("star: %zu vertices, %zu triangles", star.vertexCount(), star.triangleCount());
    m_star = m_dir.filePath(QStringLiteral("star.obj"));
    QVERIFY(test::writePlainObj(star, m_star));
    TriangleMesh open = test::axisCapsule(0.5, 1.0, 6, 10, 16);
    open.triangles.resize(open.triangles.size() - 3); // a hole at one cap
    m_open = m_dir.filePath(QStringLiteral("open-capsule.obj"));
    QVERIFY(test::writePlainObj(open, m_open));
    TRIMLAB_INIT_WIDGET_TEST();
}

std::unique_ptr<MainWindow> TestSkeletonPanel::showWindow(const QString& settingsName)
{
    return test::showMainWindow(m_dir.filePath(settingsName + QStringLiteral(".ini")), kViewportSize);
}

bool TestSkeletonPanel::openAndWait(MainWindow& window, const QString& path)
{
    QSignalSpy loaded(&window, &MainWindow::sceneLoaded);
    window.openSource(path);
    return QTest::qWaitFor([&] { return !loaded.isEmpty() && !window.isLoading(); }, kWaitMs) &&
           QTest::qWaitFor([&] { return window.viewport()->lastFrame().has_value(); }, kWaitMs);
}

bool TestSkeletonPanel::runAndWait(SkeletonPanel* panel)
{
    QSignalSpy finished(panel->task(), &BackgroundJobBase::finished);
    QTest::mouseClick(child<QPushButton>(panel, "runSkeletonButton"), Qt::LeftButton);
    return QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs);
}

bool TestSkeletonPanel::waitForNewFrame(MainWindow& window, const std::function<void()>& action)
{
    QSignalSpy frames(window.viewport(), &ViewportWidget::frameRendered);
    action();
    return QTest::qWaitFor([&] { return !frames.isEmpty(); }, kWaitMs);
}

std::unique_ptr<MainWindow> TestSkeletonPanel::extractedStar(const QString& settingsName)
{
    auto window = showWindow(settingsName);
    if (!openAndWait(*window, m_star))
        return nullptr;
    child<QDockWidget>(window.get(), "skeletonDock")->raise();
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    child<QSpinBox>(panel, "skeletonNodesSpinBox")->setValue(20);
    if (!runAndWait(panel) || !panel->result())
        return nullptr;
    return window;
}

void TestSkeletonPanel::projectionFollowsTheCamera()
{
    Camera camera; // eye (0, 0, 3) looking at the origin, y up
    const QSizeF size(200.0, 100.0);
    const auto centre = projectToWidget(camera, size, glm::dvec3(0.0));
    QVERIFY(centre);
    QCOMPARE(centre->x(), 100.0);
    QCOMPARE(centre->y(), 50.0);
    const auto up = projectToWidget(camera, size, glm::dvec3(0.0, 0.5, 0.0));
    const auto right = projectToWidget(camera, size, glm::dvec3(0.5, 0.0, 0.0));
    QVERIFY(up && right);
    QVERIFY(up->y() < 50.0); // world up is widget up
    QCOMPARE(up->x(), 100.0);
    QVERIFY(right->x() > 100.0);
    QCOMPARE(right->y(), 50.0);
    // tan(22.5°)·3 above the target is the top edge of a 45° view.
    const auto top = projectToWidget(camera, size, glm::dvec3(0.0, 3.0 * std::tan(std::numbers::pi / 8.0), 0.0));
    QVERIFY(top && std::abs(top->y()) < 1e-9);
    QVERIFY(!projectToWidget(camera, size, glm::dvec3(0.0, 0.0, 4.0))); // behind the eye
    QVERIFY(!projectToWidget(camera, size, glm::dvec3(NAN, 0.0, 0.0)));
    QVERIFY(!projectToWidget(camera, QSizeF(0.0, 10.0), glm::dvec3(0.0)));

    const std::vector<std::optional<QPointF>> points{QPointF(0, 0), QPointF(10, 0), QPointF(10, 10), std::nullopt};
    const std::vector<std::array<int, 2>> bones{{0, 1}, {1, 2}, {2, 3}};
    QCOMPARE(nearestSegment(QPointF(5, 2), points, bones, 3.0), 0);
    QCOMPARE(nearestSegment(QPointF(12, 6), points, bones, 3.0), 1);
    QCOMPARE(nearestSegment(QPointF(5, 6), points, bones, 3.0), -1);  // 4 px from the nearest
    QCOMPARE(nearestSegment(QPointF(10, 11), points, bones, 3.0), 1); // bone 2 has no tail on screen
    QCOMPARE(distanceToSegment(QPointF(3, 4), QPointF(0, 0), QPointF(0, 0)), 5.0);
}

void TestSkeletonPanel::runStagesPoseAndReset()
{
    MessageBoxCloser boxes;
    auto window = extractedStar(QStringLiteral("run"));
    QVERIFY(window);
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    ViewportWidget* viewport = window->viewport();
    const auto result = panel->result();
    const SkeletonRig& rig = result->rig;
    qInfo("rig: %zu joints, %zu bones; curve %zu nodes", rig.joints.size(), rig.bones.size(),
          result->extraction->curve.nodes.size());
    QVERIFY(rig.joints.size() >= 4); // hub and three arms at least
    QVERIFY(rig.joints.size() <= 20);
    QCOMPARE(rig.bones.size(), rig.joints.size() - 1);
    QCOMPARE(result->kind, SkeletonRunKind::Full);
    QVERIFY(!child<QLabel>(panel, "skeletonErrorLabel")->isVisible());
    auto* times = child<QTableWidget>(panel, "skeletonTimesTable");
    QCOMPARE(times->columnCount(), 6);
    QVERIFY(times->item(0, 0)->text().toDouble() > 0.0);                                   // contraction
    QVERIFY(times->item(0, 5)->text().toDouble() >= times->item(0, 0)->text().toDouble()); // total
    // The evaluator's table shows the result's own numbers; a star has no cycle, and its
    // rig keeps every bone inside.
    auto* quality = child<QTableWidget>(panel, "skeletonQualityTable");
    QCOMPARE(quality->rowCount(), 2);
    QCOMPARE(quality->item(1, 0)->text(),
             QStringLiteral("%1 %").arg(100.0 * result->rigQuality.nodesInside, 0, 'f', 1));
    QCOMPARE(result->rigQuality.nodeCount, int(rig.joints.size()));
    QCOMPARE(quality->item(1, 2)->text(), QStringLiteral("0"));
    QCOMPARE(quality->item(0, 5)->text(), QStringLiteral("0 / 0"));
    QVERIFY(result->curveQuality.samples > 0);
    // The rig's posing measures: the result's own, on one line; the star's hub roots it.
    QCOMPARE(child<QLabel>(panel, "skeletonRigMeasuresLabel")->text(),
             QStringLiteral("Rig: ") + QString::fromStdString(describeRigMeasures(result->rigMeasures)));
    QCOMPARE(result->rigMeasures.joints, int(rig.joints.size()));
    QCOMPARE(result->rigMeasures.rootBones, 3);
    QCOMPARE(result->rigMeasures.turnBacks, 0);
    QVERIFY(panel->overlay()->isVisible());
    const std::vector<glm::vec3> rest = window->scene()->scene.objects.front().mesh.positions;
    QVERIFY(panel->shownPositions() == rest); // rest pose shown

    // Stage views: each changes what the viewport shows.
    auto* view = child<QComboBox>(panel, "skeletonViewComboBox");
    QVERIFY(waitForNewFrame(*window, [&] { viewport->update(); }));
    QCOMPARE(viewport->content()->colorOwner(), render::ContentOwner::None);
    QCOMPARE(viewport->content()->poseOwner(), render::ContentOwner::Skeleton);
    const QImage posedImage = viewport->readColorImage();
    std::vector<std::vector<std::uint32_t>> seen;
    for (const SkeletonStageView stage : {SkeletonStageView::Contraction, SkeletonStageView::Mapping,
                                          SkeletonStageView::Segmentation, SkeletonStageView::Weights}) {
        QVERIFY(waitForNewFrame(*window, [&] { view->setCurrentIndex(view->findData(int(stage))); }));
        QCOMPARE(panel->view(), stage);
        QCOMPARE(viewport->content()->colorOwner(), render::ContentOwner::Skeleton);
        QVERIFY(*viewport->content()->colors() == panel->displayColors());
        QCOMPARE(panel->displayColors().size(), rest.size());
        QVERIFY(viewport->readColorImage() != posedImage);
        QVERIFY(std::find(seen.begin(), seen.end(), panel->displayColors()) == seen.end());
        seen.push_back(panel->displayColors());
        if (stage == SkeletonStageView::Contraction) {
            const auto& contracted = result->extraction->contracted;
            QCOMPARE(panel->shownPositions().size(), contracted.size());
            QCOMPARE(glm::dvec3(panel->shownPositions()[7]), glm::dvec3(glm::vec3(contracted[7])));
            QVERIFY(panel->findChild<HeatMapLegend*>()->isVisibleTo(panel));
        } else {
            QVERIFY(panel->shownPositions() == rest);
        }
    }
    const std::size_t distinctJointColors = [&] {
        std::vector<std::uint32_t> c = seen[2];
        std::sort(c.begin(), c.end());
        return std::size_t(std::unique(c.begin(), c.end()) - c.begin());
    }();
    QCOMPARE(distinctJointColors, std::size_t(std::set<int>(rig.vertexJoint.begin(), rig.vertexJoint.end()).size()));
    view->setCurrentIndex(view->findData(int(SkeletonStageView::Pose)));
    QCOMPARE(viewport->content()->colorOwner(), render::ContentOwner::None);

    // Posing with the spin boxes: a leaf bone (no bone below it) with the most weighted vertices.
    const BoneWeights& weights = result->weights->weights();
    auto weightOn = [&](std::size_t v, int bone) { return boneWeightOf(weights, v, bone); };
    const auto [bone, most] = mostWeightedLeaf(rig, weights);
    QVERIFY(bone >= 0 && most > 0);
    child<QListWidget>(panel, "skeletonBoneList")->setCurrentRow(bone);
    QCOMPARE(panel->selectedBone(), bone);
    QCOMPARE(panel->overlay()->selectedBone(), bone);
    QVERIFY(waitForNewFrame(*window, [&] { typeInto(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox"), 40.0); }));
    const std::vector<glm::vec3> posed = panel->shownPositions();
    QCOMPARE(posed.size(), rest.size());
    std::size_t moved = 0, still = 0;
    for (std::size_t v = 0; v < rest.size(); ++v) {
        const float w = weightOn(v, bone);
        if (w == 0.0f) {
            QVERIFY2(posed[v] == rest[v], qPrintable(QStringLiteral("vertex %1 without weight moved").arg(v)));
            ++still;
        } else if (w > 0.5f) {
            QVERIFY2(glm::length(posed[v] - rest[v]) > 1e-4f, qPrintable(QStringLiteral("vertex %1 stayed").arg(v)));
            ++moved;
        }
    }
    qInfo("bone %d turned 40°: %zu weighted vertices moved, %zu unweighted stayed; pose update %.3f ms", bone, moved,
          still, panel->lastPoseUpdateMs());
    QVERIFY(moved > 0 && still > 0);
    // Interactivity: the UI-thread cost of a pose update, and until the next frame is shown.
    {
        auto* box = child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox");
        double updateMs = 0.0, frameMs = 0.0;
        constexpr int kUpdates = 8;
        for (int i = 1; i <= kUpdates; ++i) {
            QElapsedTimer timer;
            timer.start();
            QVERIFY(waitForNewFrame(*window, [&] { box->setValue(40.0 + i); }));
            frameMs += double(timer.nsecsElapsed()) * 1e-6;
            updateMs += panel->lastPoseUpdateMs();
        }
        qInfo("pose update on %zu vertices: %.3f ms (skinning + showPose), %.1f ms until the frame is shown",
              rest.size(), updateMs / kUpdates, frameMs / kUpdates);
        typeInto(box, 40.0);
    }
    QCOMPARE(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox")->value(), 40.0);
    // 40° about the bone's local x, in rest axes O·q_x·O⁻¹: the same angle, cos(20°) as w.
    QVERIFY(std::abs(std::abs(panel->pose().rotations[std::size_t(bone)].w) - std::cos(glm::radians(20.0))) < 1e-9);

    // Reset pose restores the rest positions exactly.
    QTest::mouseClick(child<QPushButton>(panel, "resetSkeletonPoseButton"), Qt::LeftButton);
    QVERIFY(panel->shownPositions() == rest);
    QCOMPARE(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox")->value(), 0.0);

    // Dragging the bone in the view turns it about its head.
    auto* poseTool = child<QCheckBox>(panel, "skeletonPoseToolCheckBox");
    poseTool->setChecked(true);
    QVERIFY(!window->designWorkspace()->brushAction()->isChecked());
    const auto onScreen = screenBone(*panel, rig, bone);
    QVERIFY(onScreen);
    const auto& [head, tail] = *onScreen;
    const QPoint grab = ((head + tail) * 0.5).toPoint();
    const QPointF along = tail - head;
    const QPoint to = (head + QPointF(-along.y(), along.x())).toPoint(); // a quarter turn
    // The overlay paints the selected bone in its highlight colour over the GL frame.
    {
        const QImage shot = viewport->grab().toImage().convertToFormat(QImage::Format_RGB32);
        if (qEnvironmentVariableIsSet("TRIMLAB_TEST_OUTPUT_DIR") &&
            QDir().mkpath(qEnvironmentVariable("TRIMLAB_TEST_OUTPUT_DIR"))) {
            shot.save(
                QDir(qEnvironmentVariable("TRIMLAB_TEST_OUTPUT_DIR")).filePath(QStringLiteral("skeleton-overlay.png")));
            viewport->readColorImage().save(
                QDir(qEnvironmentVariable("TRIMLAB_TEST_OUTPUT_DIR")).filePath(QStringLiteral("skeleton-frame.png")));
        }
        const double ratio = shot.devicePixelRatio();
        const QRectF box = QRectF(head, tail).normalized().adjusted(-2, -2, 2, 2);
        int highlighted = 0;
        for (int y = int(box.top() * ratio); y <= int(box.bottom() * ratio); ++y)
            for (int x = int(box.left() * ratio); x <= int(box.right() * ratio); ++x) {
                const QColor c = shot.valid(x, y) ? shot.pixelColor(x, y) : QColor();
                highlighted += c.red() > 200 && c.green() > 150 && c.green() < 230 && c.blue() < 80 ? 1 : 0;
            }
        const QPoint mid = ((head + tail) * 0.5 * ratio).toPoint();
        qInfo("overlay: ratio %g, shot %dx%d, bone (%.1f,%.1f)-(%.1f,%.1f), mid colour %s, %d highlighted pixels",
              ratio, shot.width(), shot.height(), head.x(), head.y(), tail.x(), tail.y(),
              qPrintable(shot.pixelColor(mid).name()), highlighted);
        QVERIFY2(highlighted > 0, "no highlighted bone pixel in the viewport");
    }
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, grab);
    QCOMPARE(panel->selectedBone(), bone);
    QMouseEvent move(QEvent::MouseMove, QPointF(to), viewport->mapToGlobal(QPointF(to)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(viewport, &move);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, to);
    // The turn is the angle the cursor swept about the projected head (about a quarter
    // turn; the integer mouse positions make it a little different).
    const double swept = std::remainder(std::atan2(to.y() - head.y(), to.x() - head.x()) -
                                            std::atan2(grab.y() - head.y(), grab.x() - head.x()),
                                        2.0 * std::numbers::pi);
    const glm::dquat dragged = panel->pose().rotations[std::size_t(bone)];
    qInfo("drag: bone %.1f px long on screen, swept %.2f°, rotation w %.6f", std::hypot(along.x(), along.y()),
          glm::degrees(swept), dragged.w);
    QVERIFY(std::abs(swept) > glm::radians(30.0));
    QVERIFY(std::abs(std::abs(dragged.w) - std::cos(swept / 2.0)) < 1e-9);
    QVERIFY(panel->shownPositions() != rest);
    poseTool->setChecked(false);

    // Another node count re-selects without contracting again.
    const auto before = panel->result();
    QSignalSpy finished(panel->task(), &BackgroundJobBase::finished);
    child<QSpinBox>(panel, "skeletonNodesSpinBox")->setValue(25);
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QVERIFY(panel->result() != before);
    QCOMPARE(panel->result()->kind, SkeletonRunKind::RigOnly);
    QCOMPARE(panel->result()->extraction, before->extraction); // the same contraction, not a new one
    QVERIFY(panel->result()->rig.joints.size() <= 25);
    QCOMPARE(times->item(0, 0)->text(), QStringLiteral("–"));
    QVERIFY(panel->shownPositions() == rest); // a new rig starts at rest
    QVERIFY(boxes.seen().isEmpty());

    // A new mesh drops the result, and the bone's angles with it (they showed the last
    // run's pose on a mesh without a skeleton).
    QVERIFY(waitForNewFrame(*window, [&] { typeInto(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox"), 30.0); }));
    QSignalSpy opened(window.get(), &MainWindow::sceneLoaded);
    window->openSource(QStringLiteral("demo:sphere"));
    QVERIFY(opened.count() == 1 || opened.wait(kWaitMs));
    QVERIFY(!panel->result());
    for (const char* name : {"skeletonAngleXSpinBox", "skeletonAngleYSpinBox", "skeletonAngleZSpinBox"}) {
        QCOMPARE(child<QDoubleSpinBox>(panel, name)->value(), 0.0);
        QVERIFY(!child<QDoubleSpinBox>(panel, name)->isEnabled());
    }
}

// Posing is undoable step by step: typing 40 into one angle box (two value changes) is
// one step, another box a second, a drag in the view (many moves) a third, Reset pose a
// fourth. Undo (the button, then Ctrl+Z in the panel) walks back through exactly those
// poses to the rest mesh, bit for bit, selecting the bone each step turned; Ctrl+Shift+Z
// walks forward again. A new rig starts with nothing to undo.
void TestSkeletonPanel::poseStepsUndoAndRedo()
{
    auto window = extractedStar(QStringLiteral("undo"));
    QVERIFY(window);
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    ViewportWidget* viewport = window->viewport();
    const SkeletonRig& rig = panel->result()->rig;
    auto* undo = child<QPushButton>(panel, "undoSkeletonPoseButton");
    auto* redo = child<QPushButton>(panel, "redoSkeletonPoseButton");
    auto* bones = child<QListWidget>(panel, "skeletonBoneList");
    QVERIFY(!undo->isEnabled() && !redo->isEnabled());
    const std::vector<glm::vec3> rest = panel->shownPositions();
    const auto [bone, most] = mostWeightedLeaf(rig, panel->result()->weights->weights());
    QVERIFY(bone >= 0 && most > 0);
    const int other = bone == 0 ? 1 : 0;

    std::vector<std::vector<glm::vec3>> shown{rest};
    std::vector<SkeletonPose> poses{panel->pose()};
    auto record = [&] {
        shown.push_back(panel->shownPositions());
        poses.push_back(panel->pose());
    };
    bones->setCurrentRow(bone);
    typeInto(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox"), 40.0);
    record();
    bones->setCurrentRow(other);
    typeInto(child<QDoubleSpinBox>(panel, "skeletonAngleZSpinBox"), -25.0);
    record();
    QCOMPARE(panel->poseUndoStack()->count(), 2);
    QVERIFY(undo->isEnabled() && !redo->isEnabled());

    child<QCheckBox>(panel, "skeletonPoseToolCheckBox")->setChecked(true);
    const auto onScreen = screenBone(*panel, rig, bone);
    QVERIFY(onScreen);
    const auto& [head, tail] = *onScreen;
    const QPoint grab = ((head + tail) * 0.5).toPoint();
    const QPointF along = tail - head;
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, grab);
    for (const double t : {0.3, 0.6, 1.0}) {
        const QPoint to = (head + along * (1.0 - t) + QPointF(-along.y(), along.x()) * t).toPoint();
        QMouseEvent move(QEvent::MouseMove, QPointF(to), viewport->mapToGlobal(QPointF(to)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(viewport, &move);
    }
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, (head + QPointF(-along.y(), along.x())).toPoint());
    child<QCheckBox>(panel, "skeletonPoseToolCheckBox")->setChecked(false);
    QVERIFY(panel->pose().rotations != poses.back().rotations);
    record();
    QCOMPARE(panel->poseUndoStack()->count(), 3); // the drag is one step
    QTest::mouseClick(child<QPushButton>(panel, "resetSkeletonPoseButton"), Qt::LeftButton);
    QVERIFY(panel->shownPositions() == rest);
    record();
    QCOMPARE(panel->poseUndoStack()->count(), 4);
    QTest::mouseClick(child<QPushButton>(panel, "resetSkeletonPoseButton"), Qt::LeftButton);
    QCOMPARE(panel->poseUndoStack()->count(), 4); // at rest already: no step

    // Back: the button once, then Ctrl+Z in the panel.
    const int turned[4] = {bone, other, bone, -1}; // the bone each step turned (none: reset)
    for (int step = 3; step >= 0; --step) {
        if (step == 3)
            QTest::mouseClick(undo, Qt::LeftButton);
        else
            QTest::keyClick(bones, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY2(panel->shownPositions() == shown[std::size_t(step)], qPrintable(QString("undo to %1").arg(step)));
        QVERIFY(panel->pose().rotations == poses[std::size_t(step)].rotations);
        if (turned[step] >= 0)
            QCOMPARE(panel->selectedBone(), turned[step]);
    }
    QVERIFY(!undo->isEnabled() && redo->isEnabled());
    QCOMPARE(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox")->value(), 0.0);
    // Forward again.
    for (int step = 1; step <= 4; ++step) {
        QTest::keyClick(bones, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY2(panel->shownPositions() == shown[std::size_t(step)], qPrintable(QString("redo to %1").arg(step)));
    }
    QVERIFY(undo->isEnabled() && !redo->isEnabled());
    // Undoing the reset and the drag shows the typed angle of the first step again.
    QTest::mouseClick(undo, Qt::LeftButton);
    QTest::mouseClick(undo, Qt::LeftButton);
    QVERIFY(panel->shownPositions() == shown[2]);
    bones->setCurrentRow(bone);
    QCOMPARE(child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox")->value(), 40.0);

    // A new rig: nothing to undo.
    QSignalSpy finished(panel->task(), &BackgroundJobBase::finished);
    child<QSpinBox>(panel, "skeletonNodesSpinBox")->setValue(25);
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QCOMPARE(panel->poseUndoStack()->count(), 0);
    QVERIFY(!undo->isEnabled() && !redo->isEnabled());
}

// Posing under the dynamic rules (a classification that persists between sessions)
// moves the mesh in the view: the pose is the current set's deformation, trimmed by its
// rule. Back under the static rule the view shows the same pose at once. Before, the view
// kept the history's frame, and after switching to Static it showed the rest pose until
// the next pose change.
void TestSkeletonPanel::posingFollowsTheDynamicRules()
{
    auto window = extractedStar(QStringLiteral("dynamic-pose"));
    QVERIFY(window);
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    ViewportWidget* viewport = window->viewport();
    auto* classification = child<QComboBox>(window.get(), "classificationComboBox");
    QVERIFY(waitForNewFrame(*window, [&] { classification->setCurrentIndex(1); }));
    QVERIFY(window->designWorkspace()->showsDynamicRules());
    QVERIFY(QTest::qWaitFor([&] { return viewport->lastDynamicStats().has_value(); }, kWaitMs));
    const QImage restDynamic = viewport->readColorImage();

    const int bone = mostWeightedLeaf(panel->result()->rig, panel->result()->weights->weights()).first;
    QVERIFY(bone >= 0);
    child<QListWidget>(panel, "skeletonBoneList")->setCurrentRow(bone);
    auto* angle = child<QDoubleSpinBox>(panel, "skeletonAngleXSpinBox");
    QVERIFY(waitForNewFrame(*window, [&] { typeInto(angle, 40.0); }));
    QVERIFY(viewport->lastDynamicStats().has_value());
    QVERIFY2(viewport->errorMessage().isEmpty(), qPrintable(viewport->errorMessage()));
    QVERIFY2(viewport->readColorImage() != restDynamic, "the pose did not change the view under the dynamic rules");

    QVERIFY(waitForNewFrame(*window, [&] { classification->setCurrentIndex(0); }));
    const QImage switched = viewport->readColorImage();
    QVERIFY(waitForNewFrame(*window, [&] { angle->setValue(41.0); }));
    QVERIFY(waitForNewFrame(*window, [&] { angle->setValue(40.0); }));
    QVERIFY2(viewport->readColorImage() == switched, "after switching to Static the view did not show the pose");
}

void TestSkeletonPanel::cancelDuringRunChangesNothing()
{
    auto window = extractedStar(QStringLiteral("cancel"));
    QVERIFY(window);
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    const auto before = panel->result();
    const std::vector<glm::vec3> shown = panel->shownPositions();
    // A contraction setting changed: Run must contract again, and Cancel stops it.
    child<QCheckBox>(panel, "skeletonRefineCheckBox")->setChecked(false);
    QSignalSpy canceled(panel->task(), &BackgroundJobBase::canceled);
    QSignalSpy finished(panel->task(), &BackgroundJobBase::finished);
    QTest::mouseClick(child<QPushButton>(panel, "runSkeletonButton"), Qt::LeftButton);
    QVERIFY(panel->isRunning());
    QVERIFY(child<QProgressBar>(panel, "skeletonProgressBar")->isVisible());
    QVERIFY(!child<QPushButton>(panel, "runSkeletonButton")->isEnabled());
    QTest::mouseClick(child<QPushButton>(panel, "cancelSkeletonButton"), Qt::LeftButton);
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QCOMPARE(canceled.size(), 1);
    QVERIFY(!panel->isRunning());
    QCOMPARE(panel->result(), before);
    QVERIFY(panel->shownPositions() == shown);
    QVERIFY(!child<QProgressBar>(panel, "skeletonProgressBar")->isVisible());
    QVERIFY(child<QPushButton>(panel, "runSkeletonButton")->isEnabled());
    QVERIFY(child<QLabel>(panel, "skeletonStatusLabel")->text().contains(QStringLiteral("Canceled")));
}

void TestSkeletonPanel::openMeshIsRefusedInThePanel()
{
    MessageBoxCloser boxes;
    auto window = showWindow(QStringLiteral("open"));
    QVERIFY(openAndWait(*window, m_open));
    child<QDockWidget>(window.get(), "skeletonDock")->raise();
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    QVERIFY(runAndWait(panel));
    QVERIFY(!panel->result());
    auto* error = child<QLabel>(panel, "skeletonErrorLabel");
    qInfo("refusal: %s", qPrintable(error->text()));
    QVERIFY(!error->isHidden());
    QVERIFY(error->text().contains(QStringLiteral("boundary edge")));
    QVERIFY(child<QPushButton>(panel, "runSkeletonButton")->isEnabled());
    QVERIFY(!child<QPushButton>(panel, "exportRiggedGltfButton")->isEnabled());
    QTest::qWait(100);
    QVERIFY(boxes.seen().isEmpty()); // the panel says it; no dialog
}

void TestSkeletonPanel::exportsWriteValidFiles()
{
    auto window = extractedStar(QStringLiteral("export"));
    QVERIFY(window);
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    typeInto(child<QDoubleSpinBox>(panel, "skeletonAngleZSpinBox"), 30.0); // exported as the "pose" animation
    const QString glb = m_dir.filePath(QStringLiteral("star-rigged.glb"));
    QString error;
    QVERIFY2(panel->exportRiggedGltf(glb, &error), qPrintable(error));
    qInfo("%s: %lld bytes", qPrintable(glb), QFileInfo(glb).size());
    test::requireValidGltf(glb.toStdString());
    QVERIFY(!QTest::currentTestFailed());
    const QString json = m_dir.filePath(QStringLiteral("star-skeleton.json"));
    QVERIFY2(panel->exportSkeletonJson(json, &error), qPrintable(error));
    const SkeletonDocument document = loadSkeletonJson(json.toStdString());
    QCOMPARE(document.rig.joints, panel->result()->rig.joints);
    QCOMPARE(document.rig.vertexJoint.size(), m_starVertices);
    QVERIFY(document.curve.has_value());
    // A folder that does not exist: false and a reason naming the file.
    const QString bad = m_dir.filePath(QStringLiteral("missing/folder/rig.glb"));
    QVERIFY(!panel->exportRiggedGltf(bad, &error));
    qInfo("bad path: %s", qPrintable(error));
    QVERIFY(error.contains(QStringLiteral("rig.glb")));
}

void TestSkeletonPanel::settingsRoundTrip()
{
    SkeletonChoices choices;
    choices.extraction.contraction.initialContractionWeight = 0.002;
    choices.extraction.contraction.contractionGrowth = 3.0;
    choices.extraction.contraction.maxContractionWeight = 1024.0;
    choices.extraction.contraction.maxAttractionWeight = 5000.0;
    choices.extraction.contraction.maxIterations = 12;
    choices.extraction.contraction.ordering = SparseOrdering::Colamd;
    choices.extraction.contraction.backend = SparseBackend::EigenSimplicialLdlt;
    choices.extraction.simplification.preCollapseFraction = 0.002;
    choices.extraction.simplification.shapeWeight = 2.0;
    choices.extraction.simplification.samplingWeight = 0.3;
    choices.extraction.refine = false;
    choices.extraction.targetNodes = 35;
    choices.extraction.rootJoint = 4;
    choices.heatConstant = 0.22;
    choices.skinning = SkinningMethod::Dqs;
    const QString file = m_dir.filePath(QStringLiteral("round-trip.ini"));
    {
        QSettings settings(file, QSettings::IniFormat);
        saveSkeletonChoices(settings, choices);
    }
    auto same = [](const SkeletonChoices& a, const SkeletonChoices& b) {
        return !a.needsContraction(b) && a.extraction.targetNodes == b.extraction.targetNodes &&
               a.extraction.rootJoint == b.extraction.rootJoint && a.heatConstant == b.heatConstant &&
               a.skinning == b.skinning;
    };
    QSettings settings(file, QSettings::IniFormat);
    QVERIFY(same(loadSkeletonChoices(settings), choices));
    // Unusable values fall back field by field.
    settings.setValue(QStringLiteral("skeleton/nodes"), 20000);
    settings.setValue(QStringLiteral("skeleton/ordering"), QStringLiteral("nonsense"));
    const SkeletonChoices fallback = loadSkeletonChoices(settings);
    QCOMPARE(fallback.extraction.targetNodes, 30);
    QCOMPARE(fallback.extraction.contraction.ordering, SparseOrdering::Metis);
    QCOMPARE(fallback.heatConstant, 0.22);

    // Through the window: the form's edits are saved and come back in a new window.
    {
        auto window = showWindow(QStringLiteral("persist"));
        SkeletonPanel* panel = window->skeletonWorkspace()->panel();
        SkeletonChoices almost = choices;
        almost.extraction.targetNodes = 34;
        panel->setChoices(almost);
        typeInto(child<QSpinBox>(panel, "skeletonNodesSpinBox"), 35); // an edit saves all choices
        window->close();
    }
    auto again = showWindow(QStringLiteral("persist"));
    QVERIFY(same(again->skeletonWorkspace()->panel()->choices(), choices));
}

// The panel opens with the choices a user makes on every mesh (target nodes, root) and
// Run right after them; the solver's contraction and simplification parameters are folded
// under a toggle, closed at first, and open with it. Before, seven solver fields stood
// above Run.
void TestSkeletonPanel::runFollowsTheChoicesSolverFolded()
{
    auto window = showWindow(QStringLiteral("order"));
    SkeletonPanel* panel = window->skeletonWorkspace()->panel();
    auto y = [&](const char* name) { return child<QWidget>(panel, name)->mapTo(panel, QPoint(0, 0)).y(); };
    auto* iterations = child<QSpinBox>(panel, "skeletonIterationsSpinBox");
    QVERIFY(!iterations->isVisibleTo(panel));
    QVERIFY(child<QSpinBox>(panel, "skeletonNodesSpinBox")->isVisibleTo(panel));
    QVERIFY(y("skeletonNodesSpinBox") < y("runSkeletonButton"));
    QVERIFY(y("skeletonSolverToggle") < y("runSkeletonButton"));
    QTest::mouseClick(child<QToolButton>(panel, "skeletonSolverToggle"), Qt::LeftButton);
    QVERIFY(iterations->isVisibleTo(panel));
    QTest::mouseClick(child<QToolButton>(panel, "skeletonSolverToggle"), Qt::LeftButton);
    QVERIFY(!iterations->isVisibleTo(panel));
}

QTEST_MAIN(TestSkeletonPanel)
#include "tst_skeleton_panel.moc"
