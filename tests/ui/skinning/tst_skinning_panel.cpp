// The Skinning panel in the real main window, driven like a user: open a small animation
// through MainWindow::openAnimation(), segment it with the Segmentation panel, then Fit
// with the bones from that segmentation (or a given bone count) and compare what the
// panel shows — the E_RMS label, the per-pose chart, the heat map colors, the viewport's
// approximation — with the core's own numbers; move a bone at a pose and check that later
// poses change while earlier ones stay bit-identical, undo and redo it with the buttons
// and the keyboard, cancel a running fit, and export the result as glTF. Settings go to
// INI files in a temporary folder, never the user's.
#include "gl_test_context.h"
#include "held_background_job.h"
#include "image_artifacts.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "shown_main_window.h"
#include "posed_frame_check.h"
#include "test_paths.h"
#include "trim_comparison.h"

#include "core/skinning/skinning_error.h"
#include "core/skinning/skinning_reconstruction.h"
#include "ui/common/background_job.h"
#include "core/image/heat_map_colors.h"
#include "ui/common/heat_map_legend.h"
#include "ui/common/loaded_animation.h"
#include "ui/window/main_window.h"
#include "ui/skinning/skinning_workspace.h"
#include "ui/animation/animation_workspace.h"
#include "ui/animation/segmentation_panel.h"
#include "core/skinning/bone_edit.h"
#include "ui/skinning/skinning_error_chart.h"
#include "ui/skinning/skinning_panel.h"
#include "ui/skinning/skinning_session.h"
#include "ui/animation/timeline_panel.h"
#include "core/trim/reference_renderer.h"
#include "ui/viewport/viewport_widget.h"

#include "render/shown_content.h"

#include <QtTest>

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;
using trimlab::test::MessageBoxCloser;

namespace {

constexpr QSize kViewportSize(256, 192);
constexpr int kWaitMs = 30000;

QString testAnimation(const char* name)
{
    return QString::fromStdString(test::testDataPath(std::string("animations/") + name).string());
}

/// Types `value` into a spin box as a user would and confirms with Return.
template <class SpinBox>
void typeInto(SpinBox* box, double value)
{
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, QString::number(value));
    QTest::keyClick(box, Qt::Key_Return);
}

/// Selects the entry of `box` whose text is `text` with the keyboard (Home, then Down).
bool chooseByKeys(QComboBox* box, const QString& text)
{
    QTest::keyClick(box, Qt::Key_Home);
    for (int i = 0; i < box->count() && box->currentText() != text; ++i)
        QTest::keyClick(box, Qt::Key_Down);
    return box->currentText() == text;
}

bool samePoses(const std::vector<PosePositions>& a, const std::vector<PosePositions>& b, std::size_t pose)
{
    return pose < a.size() && pose < b.size() && a[pose] == b[pose];
}

/// The transforms, weights and rest positions of two models, compared exactly.
bool sameModel(const SkinningModel& a, const SkinningModel& b)
{
    return a.method == b.method && a.chain == b.chain && a.restPose == b.restPose &&
           a.restPositions == b.restPositions && a.weights == b.weights && a.affine == b.affine && a.rigid == b.rigid &&
           a.triangles == b.triangles;
}

} // namespace

class TestSkinningPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void fitShowsErrorChartAndLabels();
    void approximationAndHeatMapReachTheViewport();
    void boneEditPropagatesAndUndoes();
    void openingAnotherFileAsksAboutBoneEdits();
    void cancelDuringFitLeavesNoResult();
    void givenBoneCountSegmentsAnew();
    void exportWritesGltfAndReportsTheError();
    void stepInterpolationExportsStepKeys();

private:
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& settingsName);
    [[nodiscard]] static bool openAndWait(MainWindow& window, const QString& source);
    /// The folding box opened and segmented with the default choices, Skinning dock raised.
    [[nodiscard]] std::unique_ptr<MainWindow> segmentedBox(const QString& settingsName);
    /// Clicks Fit and waits for the result.
    [[nodiscard]] static bool fitAndWait(SkinningPanel* panel);
    [[nodiscard]] static bool waitForNewFrame(MainWindow& window, const std::function<void()>& action);
    /// A frame rendered now (after every change so far) against the CPU reference of the
    /// scene with object 0 at `positions`: nullopt when they agree (the animation test's
    /// criteria).
    [[nodiscard]] static std::optional<QString>
    frameDisagreement(MainWindow& window, const std::vector<glm::vec3>& positions, const QString& name);

    QTemporaryDir m_dir;
};

void TestSkinningPanel::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

std::unique_ptr<MainWindow> TestSkinningPanel::showWindow(const QString& settingsName)
{
    return test::showMainWindow(m_dir.filePath(settingsName + QStringLiteral(".ini")), kViewportSize);
}

bool TestSkinningPanel::openAndWait(MainWindow& window, const QString& source)
{
    QSignalSpy loaded(&window, &MainWindow::animationLoaded);
    window.openAnimation(source);
    return QTest::qWaitFor([&] { return !loaded.isEmpty() && !window.isLoading(); }, kWaitMs) &&
           QTest::qWaitFor([&] { return window.viewport()->lastFrame().has_value(); }, kWaitMs);
}

std::unique_ptr<MainWindow> TestSkinningPanel::segmentedBox(const QString& settingsName)
{
    auto window = showWindow(settingsName);
    if (!openAndWait(*window, testAnimation("folding_box")))
        return nullptr;
    SegmentationPanel* segmentation = window->animationWorkspace()->segmentationPanel();
    QTest::mouseClick(child<QPushButton>(segmentation, "runSegmentationButton"), Qt::LeftButton);
    if (!QTest::qWaitFor([&] { return segmentation->result() && !segmentation->isRunning(); }, kWaitMs))
        return nullptr;
    auto* dock = child<QDockWidget>(window.get(), "skinningDock");
    if (!dock->isVisible())
        return nullptr;
    dock->raise(); // as a click on its tab
    return window;
}

bool TestSkinningPanel::fitAndWait(SkinningPanel* panel)
{
    QSignalSpy finished(panel->fitTask(), &BackgroundJobBase::finished);
    QTest::mouseClick(child<QPushButton>(panel, "fitSkinningButton"), Qt::LeftButton);
    return QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs) && panel->session() != nullptr;
}

bool TestSkinningPanel::waitForNewFrame(MainWindow& window, const std::function<void()>& action)
{
    return test::waitForFrameAfter(window, action, kWaitMs);
}

std::optional<QString> TestSkinningPanel::frameDisagreement(MainWindow& window, const std::vector<glm::vec3>& positions,
                                                            const QString& name)
{
    // A frame already reported may have been painted while the change was being made.
    if (!waitForNewFrame(window, [&] { window.viewport()->update(); }))
        return name + QStringLiteral(": no frame rendered");
    return test::posedFrameDisagreement(window, positions, name);
}

// Fit with the bones from the segmentation: one bone per segment, one chart point per
// pose equal to the core's per-pose E_RMS, the overall E_RMS in the label, the marker on
// the timeline's pose.
void TestSkinningPanel::fitShowsErrorChartAndLabels()
{
    auto window = segmentedBox(QStringLiteral("fit"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    const VertexLabeling segmentation = *window->animationWorkspace()->segmentationPanel()->shownLabeling();
    QVERIFY(segmentation.count >= 1);
    QCOMPARE(child<QComboBox>(panel, "skinningBoneSourceComboBox")->currentText(),
             QStringLiteral("From the segmentation"));
    QVERIFY2(child<QLabel>(panel, "skinningBoneCountLabel")->text().contains(QString::number(segmentation.count)),
             qPrintable(child<QLabel>(panel, "skinningBoneCountLabel")->text()));
    QVERIFY(!child<QPushButton>(panel, "cancelSkinningButton")->isEnabled());

    QVERIFY(fitAndWait(panel));
    const SkinningFit& fit = panel->session()->fit();
    const std::size_t poses = window->animation()->animation->poseCount();
    QCOMPARE(fit.bones, segmentation);
    QCOMPARE(fit.result.model.boneCount(), std::size_t(segmentation.count));
    QCOMPARE(fit.result.model.poseCount(), poses);
    QCOMPARE(child<QListWidget>(panel, "skinningBoneList")->count(), int(segmentation.count));
    QVERIFY(!panel->session()->isEdited());

    // The core's own numbers: the reconstruction and error of the fitted model.
    const std::vector<PosePositions> reconstructed = reconstructPoses(fit.result.model);
    QVERIFY(reconstructed == panel->session()->approximation());
    const SkinningError measured = measureSkinningError(animationPositions(*window->animation()->animation),
                                                        reconstructed, fit.result.model.restPose);
    QCOMPARE(measured.eRms, fit.result.error.eRms);

    const QList<QPointF> points = panel->errorChart()->points();
    QCOMPARE(points.size(), qsizetype(poses));
    for (qsizetype pose = 0; pose < points.size(); ++pose) {
        QCOMPARE(points[pose].x(), double(pose));
        QCOMPARE(points[pose].y(), fit.result.error.perPose[std::size_t(pose)]);
    }
    QVERIFY(panel->errorChart()->fittedPoints().isEmpty());
    const QString label = child<QLabel>(panel, "skinningErrorLabel")->text();
    QVERIFY2(label.contains(SkinningPanel::formatERms(fit.result.error.eRms)), qPrintable(label));
    QVERIFY2(child<QLabel>(panel, "skinningTimesLabel")->text().contains(QStringLiteral("total")),
             qPrintable(child<QLabel>(panel, "skinningTimesLabel")->text()));
    QVERIFY(child<QLabel>(panel, "skinningStatusLabel")->text().startsWith(QStringLiteral("Done")));

    QCOMPARE(panel->errorChart()->markerPose(), 0);
    auto* slider = child<QSlider>(window.get(), "poseSlider");
    QTest::keyClick(slider, Qt::Key_End);
    QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), int(poses) - 1);
    QCOMPARE(panel->errorChart()->markerPose(), int(poses) - 1);
}

// Show ▸ Approximation puts the reconstructed pose in the viewport, skinned on the GPU
// (checked against the CPU reference of the CPU's pose); Show ▸ Error heat map colors the vertices by their error
// with a legend; Show ▸ Original goes back to the original poses and segment colors.
void TestSkinningPanel::approximationAndHeatMapReachTheViewport()
{
    auto window = segmentedBox(QStringLiteral("views"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    auto* view = child<QComboBox>(panel, "skinningViewComboBox");
    QVERIFY(!view->isEnabled());
    QVERIFY(fitAndWait(panel));
    QVERIFY(view->isEnabled());
    const std::vector<std::uint32_t> segmentColors = window->animationWorkspace()->segmentationPanel()->displayColors();
    QVERIFY(!segmentColors.empty());

    auto* slider = child<QSlider>(window.get(), "poseSlider");
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_End); }));
    const int last = window->animationWorkspace()->timelinePanel()->pose();
    bool chosen = false;
    QVERIFY(waitForNewFrame(*window, [&] { chosen = chooseByKeys(view, QStringLiteral("Approximation")); }));
    QVERIFY(chosen);
    QCOMPARE(panel->view(), SkinningView::Approximation);
    const std::vector<glm::vec3> approximate = panel->session()->approximatePose(std::size_t(last));
    QVERIFY(panel->shownPose(last) == approximate);
    if (const auto problem = frameDisagreement(*window, approximate, QStringLiteral("skinning-approximation")))
        QFAIL(qPrintable(*problem));
    QCOMPARE(window->viewport()->poseEvaluation(), render::PoseEvaluation::GpuSkinning); // the frame above
    QCOMPARE(window->viewport()->content()->poseOwner(), render::ContentOwner::Skinning);

    QVERIFY(waitForNewFrame(*window, [&] { chosen = chooseByKeys(view, QStringLiteral("Error heat map")); }));
    QVERIFY(chosen);
    QVERIFY(!panel->shownPose(last)); // the heat map lies on the original poses
    // The errors of the pose shown, on the scale of the largest error of any pose.
    const SkinningSession& session = *panel->session();
    const auto poseMap = [&](int pose) {
        return heatMapRgba8(poseVertexErrors(session.fit().original.at(std::size_t(pose)),
                                             session.approximation().at(std::size_t(pose))),
                            session.error().maxDistance);
    };
    QCOMPARE(panel->displayColors().size(), window->animation()->animation->vertexCount());
    QCOMPARE(panel->displayColors(), poseMap(last));
    QVERIFY(panel->displayColors() != segmentColors);
    QCOMPARE(window->viewport()->content()->colorOwner(), render::ContentOwner::Skinning);
    QVERIFY(*window->viewport()->content()->colors() == panel->displayColors());
    auto* legend = child<HeatMapLegend>(panel, "heatMapLegend");
    QVERIFY(legend->isVisible());
    QCOMPARE(legend->maxValue(), session.error().maxDistance);
    QVERIFY(heatMapColor(0.0) != heatMapColor(1.0));
    // It follows the timeline: the first pose's own errors, shown in the view.
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_Home); }));
    QCOMPARE(panel->displayColors(), poseMap(0));
    QVERIFY(*window->viewport()->content()->colors() == poseMap(0));
    QVERIFY(waitForNewFrame(*window, [&] { QTest::keyClick(slider, Qt::Key_End); }));
    QCOMPARE(panel->displayColors(), poseMap(last));

    QVERIFY(waitForNewFrame(*window, [&] { chosen = chooseByKeys(view, QStringLiteral("Original")); }));
    QVERIFY(chosen);
    QVERIFY(panel->displayColors().empty());
    QVERIFY(!legend->isVisible());
    QVERIFY(!panel->shownPose(last));
    QCOMPARE(window->viewport()->content()->colorOwner(),
             render::ContentOwner::Segmentation); // the segment colors again
    QVERIFY(*window->viewport()->content()->colors() == segmentColors);
    if (const auto problem = frameDisagreement(*window, window->animation()->animation->poses[std::size_t(last)],
                                               QStringLiteral("skinning-original")))
        QFAIL(qPrintable(*problem));
    QCOMPARE(window->viewport()->poseEvaluation(), render::PoseEvaluation::Uploaded);
    QCOMPARE(window->viewport()->content()->poseOwner(), render::ContentOwner::AnimationPlayback);
}

// Moving a bone at pose 1 changes poses 1 and 2, leaves pose 0 bit-identical, and equals
// the core's edit of the fitted model; a second edit at pose 2 leaves poses 0 and 1 as
// they were. Undo (button, then Ctrl+Z in the panel) gives back the fitted model exactly;
// redo (Ctrl+Shift+Z) the edited one.
void TestSkinningPanel::boneEditPropagatesAndUndoes()
{
    auto window = segmentedBox(QStringLiteral("edit"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    auto* apply = child<QPushButton>(panel, "applyBoneEditButton");
    auto* undo = child<QPushButton>(panel, "undoSkinningEditButton");
    auto* redo = child<QPushButton>(panel, "redoSkinningEditButton");
    // Propagation is the pose-to-pose chain's (thesis 4.1.3): the thesis's LBS, no corrections.
    QVERIFY(chooseByKeys(child<QComboBox>(panel, "skinningMethodComboBox"), QStringLiteral("LBS (affine bones)")));
    QCOMPARE(panel->choices().chain, SkinningChain::PoseToPose);
    QTest::keyClick(child<QCheckBox>(panel, "weightCorrectionsCheckBox"), Qt::Key_Space);
    QTest::keyClick(child<QCheckBox>(panel, "vertexCorrectionsCheckBox"), Qt::Key_Space);
    QVERIFY(fitAndWait(panel));
    SkinningSession* session = panel->session();
    const std::shared_ptr<const SkinningModel> fitted = session->model();
    const std::vector<PosePositions> fittedPoses = session->approximation();
    const double fittedERms = session->error().eRms;
    QVERIFY(!apply->isEnabled()); // pose 0 is the rest pose
    QVERIFY(!undo->isEnabled());
    QVERIFY(chooseByKeys(child<QComboBox>(panel, "skinningViewComboBox"), QStringLiteral("Approximation")));

    auto* slider = child<QSlider>(window.get(), "poseSlider");
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), 1);
    QVERIFY(apply->isEnabled());
    auto* bones = child<QListWidget>(panel, "skinningBoneList");
    const int bone = bones->count() - 1;
    QTest::mouseClick(bones->viewport(), Qt::LeftButton, {}, bones->visualItemRect(bones->item(bone)).center());
    QCOMPARE(bones->currentRow(), bone);
    typeInto(child<QDoubleSpinBox>(panel, "boneRotateZSpinBox"), 30.0);
    typeInto(child<QDoubleSpinBox>(panel, "boneMoveYSpinBox"), 0.25);
    BoneEdit edit;
    edit.rotationDegrees = {0.0, 0.0, 30.0};
    edit.translation = {0.0, 0.25, 0.0};
    QVERIFY(waitForNewFrame(*window, [&] { QTest::mouseClick(apply, Qt::LeftButton); }));
    QCOMPARE(child<QDoubleSpinBox>(panel, "boneRotateZSpinBox")->value(), 0.0); // the change was applied

    const SkinningModel expected = applyBoneEdit(*fitted, 1, std::size_t(bone), edit, fittedPoses[1]);
    QVERIFY(session->isEdited());
    QVERIFY(sameModel(*session->model(), expected));
    const std::vector<PosePositions> firstEdit = session->approximation();
    QVERIFY(firstEdit == reconstructPoses(expected));
    QVERIFY(samePoses(firstEdit, fittedPoses, 0));
    QVERIFY(!samePoses(firstEdit, fittedPoses, 1));
    QVERIFY(!samePoses(firstEdit, fittedPoses, 2));
    const SkinningError editedError =
        measureSkinningError(session->fit().original, firstEdit, session->model()->restPose);
    QCOMPARE(session->error().eRms, editedError.eRms);
    QVERIFY(editedError.eRms > fittedERms);
    QVERIFY(child<QLabel>(panel, "skinningErrorLabel")->text().contains(SkinningPanel::formatERms(editedError.eRms)));
    // Every error the label quotes has its unit, the fitted one beside the edit too.
    const QString fittedText =
        QStringLiteral("fitted E_RMS %1 thousandths").arg(SkinningPanel::formatERms(session->fit().result.error.eRms));
    QVERIFY2(child<QLabel>(panel, "skinningErrorLabel")->text().contains(fittedText),
             qPrintable(child<QLabel>(panel, "skinningErrorLabel")->text()));
    QCOMPARE(panel->errorChart()->points().at(1).y(), editedError.perPose[1]);
    QCOMPARE(panel->errorChart()->fittedPoints().size(), qsizetype(fittedPoses.size()));
    // The frame shows the edited approximation, which is far from the original pose.
    const std::vector<glm::vec3> editedPose = session->approximatePose(1);
    const std::vector<glm::vec3>& originalPose = window->animation()->animation->poses[1];
    float moved = 0.0f;
    for (std::size_t j = 0; j < editedPose.size(); ++j)
        moved = std::max(moved, glm::distance(editedPose[j], originalPose[j]));
    QVERIFY2(moved > 0.2f, qPrintable(QString::number(moved)));
    if (const auto problem = frameDisagreement(*window, editedPose, QStringLiteral("skinning-edited")))
        QFAIL(qPrintable(*problem));
    QVERIFY(undo->isEnabled());
    QVERIFY(!redo->isEnabled());
    const std::filesystem::path picture = test::outputDir() / "skinning-panel-edited.png";
    QVERIFY(panel->grab().save(QString::fromStdString(picture.string())));

    // A second edit at pose 2: poses 0 and 1 stay exactly as the first edit left them.
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(window->animationWorkspace()->timelinePanel()->pose(), 2);
    typeInto(child<QDoubleSpinBox>(panel, "boneRotateXSpinBox"), -20.0);
    QTest::mouseClick(apply, Qt::LeftButton);
    QCOMPARE(session->undoStack()->count(), 2);
    QVERIFY(samePoses(session->approximation(), firstEdit, 0));
    QVERIFY(samePoses(session->approximation(), firstEdit, 1));
    QVERIFY(!samePoses(session->approximation(), firstEdit, 2));
    const std::shared_ptr<const SkinningModel> secondEdit = session->model();

    // Undo with the button, then with Ctrl+Z while the bone list has the focus.
    QTest::mouseClick(undo, Qt::LeftButton);
    QVERIFY(sameModel(*session->model(), expected));
    QVERIFY(session->approximation() == firstEdit);
    bones->setFocus();
    QTest::keyClick(bones, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(session->model(), fitted);
    QVERIFY(!session->isEdited());
    QVERIFY(sameModel(*session->model(), panel->session()->fit().result.model));
    QVERIFY(session->approximation() == fittedPoses);
    QVERIFY(session->approximation() == reconstructPoses(*session->model()));
    QCOMPARE(session->error().eRms, fittedERms);
    QVERIFY(child<QLabel>(panel, "skinningErrorLabel")->text().contains(SkinningPanel::formatERms(fittedERms)));
    QVERIFY(panel->errorChart()->fittedPoints().isEmpty());
    QVERIFY(!undo->isEnabled());
    QVERIFY(redo->isEnabled());

    // Redo twice with Ctrl+Shift+Z: the very models of the edits come back.
    QTest::keyClick(bones, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(sameModel(*session->model(), expected));
    QTest::mouseClick(redo, Qt::LeftButton);
    QCOMPARE(session->model(), secondEdit);
}

// Bone edits are the user's work: opening another animation asks before discarding them
// (it discarded them silently). Cancel keeps the animation and its edits; Discard opens
// the other file; with every edit undone nothing is asked.
void TestSkinningPanel::openingAnotherFileAsksAboutBoneEdits()
{
    auto window = segmentedBox(QStringLiteral("unexported"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    QVERIFY(fitAndWait(panel));
    QTest::keyClick(child<QSlider>(window.get(), "poseSlider"), Qt::Key_Right);
    auto* bones = child<QListWidget>(panel, "skinningBoneList");
    bones->setCurrentRow(bones->count() - 1);
    typeInto(child<QDoubleSpinBox>(panel, "boneRotateZSpinBox"), 30.0);
    QTest::mouseClick(child<QPushButton>(panel, "applyBoneEditButton"), Qt::LeftButton);
    QVERIFY(panel->session()->isEdited());
    const QString box = testAnimation("folding_box");
    const QString bar = testAnimation("bar");
    {
        test::MessageBoxAnswerer cancel(QMessageBox::Cancel);
        window->openAnimation(bar);
        QCOMPARE(cancel.names(), QStringList{QStringLiteral("unexportedSkinningEditsBox")});
        QVERIFY(cancel.seen().front().contains(QStringLiteral("not exported")));
    }
    QVERIFY(!window->isLoading());
    QCOMPARE(QString::fromStdString(window->scene()->source), box);
    QVERIFY(panel->session() && panel->session()->isEdited());
    {
        test::MessageBoxAnswerer discard(QMessageBox::Discard);
        QVERIFY(openAndWait(*window, bar));
        QCOMPARE(discard.names().size(), 1);
    }
    QVERIFY(!panel->session());
    // Undone edits are no work to lose.
    QVERIFY(openAndWait(*window, box));
    SegmentationPanel* segmentation = window->animationWorkspace()->segmentationPanel();
    QTest::mouseClick(child<QPushButton>(segmentation, "runSegmentationButton"), Qt::LeftButton);
    QVERIFY(QTest::qWaitFor([&] { return segmentation->result() && !segmentation->isRunning(); }, kWaitMs));
    QVERIFY(fitAndWait(panel));
    QTest::keyClick(child<QSlider>(window.get(), "poseSlider"), Qt::Key_Right);
    bones->setCurrentRow(bones->count() - 1);
    typeInto(child<QDoubleSpinBox>(panel, "boneRotateZSpinBox"), 30.0);
    QTest::mouseClick(child<QPushButton>(panel, "applyBoneEditButton"), Qt::LeftButton);
    QVERIFY(panel->session()->isEdited());
    QTest::mouseClick(child<QPushButton>(panel, "undoSkinningEditButton"), Qt::LeftButton);
    QVERIFY(!panel->session()->isEdited());
    test::MessageBoxAnswerer none(QMessageBox::Cancel);
    QVERIFY(openAndWait(*window, bar));
    QVERIFY(none.names().isEmpty());
}

// Cancel while the fit runs (held at its first progress report): no result, the Fit
// button comes back, nothing is shown, and a later fit works.
void TestSkinningPanel::cancelDuringFitLeavesNoResult()
{
    auto window = segmentedBox(QStringLiteral("cancel"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    test::HeldBackgroundJob held(panel->fitTask());
    auto* fit = child<QPushButton>(panel, "fitSkinningButton");
    auto* cancel = child<QPushButton>(panel, "cancelSkinningButton");
    QTest::mouseClick(fit, Qt::LeftButton);
    QVERIFY(held.waitUntilHeld(kWaitMs));
    QVERIFY(panel->isRunning());
    QVERIFY(!fit->isEnabled());
    QVERIFY(child<QProgressBar>(panel, "skinningProgressBar")->isVisible());
    QVERIFY(cancel->isEnabled());
    QTest::mouseClick(cancel, Qt::LeftButton);
    QVERIFY(!cancel->isEnabled()); // canceling
    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !panel->isRunning(); }, kWaitMs));
    QVERIFY(!panel->session());
    QVERIFY(fit->isEnabled());
    QVERIFY(!child<QProgressBar>(panel, "skinningProgressBar")->isVisible());
    QVERIFY(child<QLabel>(panel, "skinningStatusLabel")->text().contains(QStringLiteral("Canceled")));
    QVERIFY(panel->errorChart()->points().isEmpty());
    QVERIFY(!child<QComboBox>(panel, "skinningViewComboBox")->isEnabled());

    held.stop();
    QVERIFY(fitAndWait(panel));
    QCOMPARE(panel->errorChart()->points().size(), qsizetype(window->animation()->animation->poseCount()));
}

// Bones: Given count re-segments into exactly that many segments and fits them, here
// with DQS and both corrections; a DQS bone edit propagates like an LBS one.
void TestSkinningPanel::givenBoneCountSegmentsAnew()
{
    auto window = segmentedBox(QStringLiteral("given"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    auto* count = child<QSpinBox>(panel, "skinningBoneCountSpinBox");
    QVERIFY(!count->isEnabled());
    QVERIFY(chooseByKeys(child<QComboBox>(panel, "skinningBoneSourceComboBox"), QStringLiteral("Given count")));
    QVERIFY(count->isEnabled());
    typeInto(count, 3);
    // The corrections are on by default; the chain box is disabled under the rigid-joint fit.
    QVERIFY(panel->choices().fitExported);
    QVERIFY(!child<QComboBox>(panel, "skinningChainComboBox")->isEnabled());
    auto* influences = child<QSpinBox>(panel, "skinningInfluencesSpinBox");
    QCOMPARE(influences->value(), 4);
    QVERIFY(influences->isEnabled());
    typeInto(influences, 6);
    QCOMPARE(panel->choices().fitOptions().decomposition.maxInfluences, std::size_t(6));
    QVERIFY(chooseByKeys(child<QComboBox>(panel, "skinningMethodComboBox"), QStringLiteral("DQS (rigid bones)")));
    QVERIFY(child<QComboBox>(panel, "skinningChainComboBox")->isEnabled());
    QVERIFY(influences->isEnabled()); // every fit keeps the limit
    QCOMPARE(panel->choices().fitOptions().decomposition.maxInfluences, std::size_t(6));
    const SkinningChoices chosen = panel->choices();
    QVERIFY(!chosen.fitExported);
    QCOMPARE(chosen.boneSource, BoneSource::GivenCount);
    QCOMPARE(chosen.boneCount, 3);
    QCOMPARE(chosen.method, SkinningMethod::Dqs);
    QVERIFY(chosen.weightCorrections && chosen.vertexCorrections);
    QVERIFY(fitAndWait(panel));
    SkinningSession* session = panel->session();
    QCOMPARE(session->fit().bones.count, 3u);
    QCOMPARE(session->model()->boneCount(), std::size_t(3));
    QCOMPARE(session->model()->method, SkinningMethod::Dqs);
    QVERIFY(session->fit().result.times.weightCorrectionMs > 0.0);
    QVERIFY(session->fit().result.times.vertexCorrectionMs > 0.0);
    const QString times = child<QLabel>(panel, "skinningTimesLabel")->text();
    QVERIFY2(times.contains(QStringLiteral("weight corrections")) &&
                 times.contains(QStringLiteral("vertex corrections")),
             qPrintable(times));
    QCOMPARE(child<QListWidget>(panel, "skinningBoneList")->count(), 3);

    const std::vector<PosePositions> fitted = session->approximation();
    QTest::keyClick(child<QSlider>(window.get(), "poseSlider"), Qt::Key_Right);
    typeInto(child<QDoubleSpinBox>(panel, "boneRotateYSpinBox"), 45.0);
    QTest::mouseClick(child<QPushButton>(panel, "applyBoneEditButton"), Qt::LeftButton);
    QVERIFY(session->isEdited());
    QVERIFY(samePoses(session->approximation(), fitted, 0));
    QVERIFY(!samePoses(session->approximation(), fitted, 1));
    QVERIFY(!samePoses(session->approximation(), fitted, 2));
}

// The export the window starts after its file dialog: the file is written on a worker and
// the window reports the file's E_RMS against the original animation.
void TestSkinningPanel::exportWritesGltfAndReportsTheError()
{
    auto window = segmentedBox(QStringLiteral("export"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    auto* button = child<QPushButton>(panel, "exportSkinningButton");
    QVERIFY(!button->isEnabled());
    QVERIFY(fitAndWait(panel));
    QVERIFY(button->isEnabled());
    MessageBoxCloser closer;
    QSignalSpy finished(panel, &SkinningPanel::exportFinished);
    const QString path = m_dir.filePath(QStringLiteral("box-skinned.glb"));
    panel->exportGltf(path, 24.0);
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QVERIFY(std::filesystem::file_size(path.toStdString()) > 0);
    const double eRms = finished.front().at(1).toDouble();
    QVERIFY(std::isfinite(eRms));
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, kWaitMs));
    const QString shown = closer.seen().front();
    QVERIFY2(shown.contains(path) && shown.contains(SkinningPanel::formatERms(eRms)), qPrintable(shown));
    QVERIFY(button->isEnabled());
}

// The export's keyframes, as `trimlab skin --interpolation`: Step writes STEP samplers only;
// morph targets have none to choose.
void TestSkinningPanel::stepInterpolationExportsStepKeys()
{
    auto window = segmentedBox(QStringLiteral("step"));
    QVERIFY(window);
    SkinningPanel* panel = window->animationWorkspace()->skinning()->panel();
    QVERIFY(fitAndWait(panel));
    auto* interpolation = child<QComboBox>(panel, "skinningInterpolationComboBox");
    QVERIFY(chooseByKeys(interpolation, QStringLiteral("Step")));
    MessageBoxCloser closer;
    QSignalSpy finished(panel, &SkinningPanel::exportFinished);
    const QString path = m_dir.filePath(QStringLiteral("box-step.gltf"));
    panel->exportGltf(path, 24.0);
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonArray animations = QJsonDocument::fromJson(file.readAll()).object().value("animations").toArray();
    QVERIFY(!animations.isEmpty());
    int samplers = 0;
    for (const QJsonValue& animation : animations)
        for (const QJsonValue& sampler : animation.toObject().value("samplers").toArray()) {
            QCOMPARE(sampler.toObject().value("interpolation").toString(), QStringLiteral("STEP"));
            ++samplers;
        }
    QVERIFY(samplers > 0);
    auto* morph = child<QCheckBox>(panel, "skinningMorphTargetsCheckBox");
    QVERIFY(morph->isEnabled() && !morph->isChecked());
    morph->click(); // the panel may be scrolled so that a mouse click misses it
    QVERIFY(!interpolation->isEnabled());
}

QTEST_MAIN(TestSkinningPanel)
#include "tst_skinning_panel.moc"
