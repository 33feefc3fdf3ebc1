#pragma once
/// \file
/// The Skeleton panel (the content of the main window's "Skeleton" dock): skeleton
/// extraction by mesh contraction (Berenguer & Moreno; core/skeleton/) on the mesh shown,
/// every stage visible, the rig posed live, and the exports.
///
/// - Parameters of every stage (skeleton_settings_form.h); the window persists them
///   (skeleton_settings_store.h) on choicesChanged().
/// - Run: on a worker (BackgroundJob) the pipeline of core/skeleton/skeleton_pipeline.h —
///   stages A–D, the bone-heat weights with the form's heat constant, the evaluation —
///   with the running stage's name and bar and Cancel, which keeps the previous result
///   (job_presenter.h). When only the node count or the root differs from the last run's
///   choices, Run (and, after a short pause, any change of those two) re-runs only
///   selectRig and the weights on the kept curve skeleton (rerunSkeletonRig). The scene must be one
///   closed, manifold, connected object; otherwise the refusal (SkeletonInputError's
///   text) shows in the panel's error label — no dialog.
/// - Show (stage views, skeleton_stage_colors.h): the posed mesh; the contracted mesh by
///   ‖L·V′‖ (Fig. 7, with a legend); the mesh–curve mapping (Fig. 8); the segmentation by
///   joint (Fig. 10); the selected bone's weights (Fig. 12, with a legend).
/// - The rig is drawn over the view (skeleton_overlay.h), the selected bone highlighted.
/// - Posing: select a bone in the list or, with "Pose with the mouse" on, by clicking
///   near it in the view and drag to turn it about its head in the view plane
///   (skeleton_pose_tool.h); three spin boxes give its rotation in degrees about x/y/z of
///   the bone's local frame (skeleton_pose_edit.h). The mesh is skinned (LBS or DQS) on
///   every change and published as the skeleton's pose (render/content_publisher.h), so
///   the trim renderer shows the self-trimmed solid where the pose makes the surface
///   cross itself — under the dynamic rules too, whose chain the design history ends in
///   the pose shown. Reset pose goes back to the rest pose.
/// - Posing undo: every pose change is a step on the panel's own undo stack
///   (skeleton_pose_command.h; one mouse drag, or a run of edits of one angle box, is one
///   step): Undo/Redo beside Reset pose, and Ctrl+Z / Ctrl+Shift+Z while the panel has
///   focus (claimed there, so the window's Edit ▸ Undo of strokes is not reached). A new
///   result or scene starts an empty stack.
/// - Export rigged glTF… / Export skeleton JSON… (exportGltfRequested() /
///   exportJsonRequested(): the window asks for a file and calls exportRiggedGltf() /
///   exportSkeletonJson()).
/// - The stage times of the last run in the columns of the paper's Table III.
///
/// The panel publishes into the content of the viewport it is given (setViewport), as
/// the skeleton: object 0's positions and the stage colours while it has a result.

#include "ui/common/background_job.h"
#include "ui/skeleton/skeleton_choices.h"

#include "render/content_publisher.h"

#include "core/catalog/scene_source.h"
#include "core/skeleton/skeleton_pipeline.h"
#include "core/skeleton/skeleton_pose.h"

#include <QPointer>
#include <QString>
#include <QUndoStack>
#include <QWidget>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTimer;

namespace trimlab::ui {

class HeatMapLegend;
class JobPresenter;
class SkeletonOverlay;
class SkeletonPoseTool;
class SkeletonSettingsForm;
class UndoButtons;
class ViewportWidget;

class SkeletonPanel : public QWidget {
    Q_OBJECT
public:
    explicit SkeletonPanel(QWidget* parent = nullptr);
    ~SkeletonPanel() override;

    /// The view to show stages and poses in; creates the overlay and the pose tool.
    void setViewport(ViewportWidget* viewport);
    /// The scene shown (nullptr: none). Cancels a running job and forgets the result.
    void setScene(std::shared_ptr<const LoadedScene> scene);

    void setChoices(const SkeletonChoices& choices);
    [[nodiscard]] SkeletonChoices choices() const;

    /// Run's click (no-op without a usable scene or while running).
    void run();
    void cancel();
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] BackgroundJobBase* task() const { return m_job; }
    /// The last successful run (nullptr before one on this scene).
    [[nodiscard]] std::shared_ptr<const SkeletonResult> result() const { return m_result; }

    void setView(SkeletonStageView view);
    [[nodiscard]] SkeletonStageView view() const { return m_view; }
    /// Selects bone `bone` (−1: none) in the list, the overlay and the spin boxes.
    void selectBone(int bone);
    [[nodiscard]] int selectedBone() const { return m_selectedBone; }
    /// Turns the selected bone by `radians` about the world `axis` through its posed head.
    void rotateBone(int bone, const glm::dvec3& worldAxis, double radians);
    void resetPose();
    [[nodiscard]] const SkeletonPose& pose() const { return m_pose; }
    [[nodiscard]] QUndoStack* poseUndoStack() { return &m_poseUndo; }
    /// Object 0's positions as last handed to the viewport, and the colours (#V or empty).
    [[nodiscard]] const std::vector<glm::vec3>& shownPositions() const { return m_shown; }
    [[nodiscard]] const std::vector<std::uint32_t>& displayColors() const { return m_colors; }
    /// The skinned positions of the current pose (#V; empty without a result).
    [[nodiscard]] const std::vector<glm::vec3>& posedPositions() const { return m_posed; }
    /// Milliseconds the last pose update took on the UI thread: forward kinematics,
    /// skinning and handing the positions to the viewport (not the frame itself).
    [[nodiscard]] double lastPoseUpdateMs() const { return m_poseUpdateMs; }

    /// "Pose with the mouse": installs the pose tool on the viewport (poseToolToggled(true)
    /// first, so that the window can switch the brush off).
    void setPoseToolEnabled(bool enabled);
    /// Another tool took the viewport: unchecks without touching the viewport's tool.
    void poseToolTakenOver();
    [[nodiscard]] SkeletonPoseTool* poseTool() const { return m_tool; }
    [[nodiscard]] SkeletonOverlay* overlay() const;

    /// Writes the rigged mesh (rest pose; with the current pose as the animation "pose"
    /// when it is not the rest pose). False with the reason in `error` on failure.
    bool exportRiggedGltf(const QString& path, QString* error = nullptr);
    bool exportSkeletonJson(const QString& path, QString* error = nullptr);

signals:
    void choicesChanged();
    void resultChanged();
    void exportGltfRequested();
    void exportJsonRequested();
    void poseToolToggled(bool on);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    QWidget* createRunRow();
    QWidget* createViewGroup();
    QTableWidget* createQualityTable();
    QWidget* createPoseGroup();
    QWidget* createExportRow();
    void connectJob();
    void onSucceeded();
    void onEnded(const QString& status);
    void onBoneAnglesEdited();
    void showResult();
    void showTimes();
    void showQuality();
    void updatePose();
    /// Pushes the change from m_pose to `after` as one step of the gesture of `source`
    /// (kMouseGesture or an angle box 0–2) on `bone`.
    void pushPose(const SkeletonPose& after, int bone, int source, const QString& text);
    void applyPose(const SkeletonPose& pose, int bone, bool refreshAngles);
    void closeGesture() { m_gestureSource = kNoGesture; }
    void applyDisplay();
    void showPositions();
    void updateAngleBoxes();
    void updateControls();
    [[nodiscard]] QString readyStatus() const;

    SkeletonSettingsForm* m_form = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_error = nullptr;
    QTableWidget* m_times = nullptr;
    QTableWidget* m_quality = nullptr;
    QLabel* m_rigMeasures = nullptr; ///< joints, root bones, turn-backs, leakage (rig_measures.h)
    QComboBox* m_viewBox = nullptr;
    HeatMapLegend* m_legend = nullptr;
    QWidget* m_poseGroup = nullptr;
    QListWidget* m_boneList = nullptr;
    QDoubleSpinBox* m_angles[3] = {nullptr, nullptr, nullptr};
    QCheckBox* m_poseTool = nullptr;
    QPushButton* m_resetPose = nullptr;
    UndoButtons* m_poseUndoButtons = nullptr;
    QPushButton* m_rootHere = nullptr;
    QPushButton* m_exportGltf = nullptr;
    QPushButton* m_exportJson = nullptr;
    QTimer* m_rerunTimer = nullptr;

    BackgroundJob<std::shared_ptr<const SkeletonResult>>* m_job = nullptr;
    JobPresenter* m_presenter = nullptr;
    QPointer<ViewportWidget> m_viewport; ///< the window may destroy it before the panel
    render::ContentPublisher m_content;  ///< the skeleton's pose and colours in the viewport's content
    QPointer<SkeletonOverlay> m_overlay; ///< a child of the viewport
    SkeletonPoseTool* m_tool = nullptr;
    bool m_toolInstalled = false;

    std::shared_ptr<const LoadedScene> m_scene;
    std::shared_ptr<const TriangleMesh> m_mesh; ///< object 0 (object space); null when unusable
    glm::dmat4 m_model{1.0};
    QString m_unusable; ///< why the scene cannot be used ("" when it can)
    std::shared_ptr<const SkeletonResult> m_result;
    SkeletonChoices m_resultChoices; ///< what m_result was made with
    SkeletonChoices m_runChoices;    ///< what the running job was started with
    SkeletonPose m_pose;
    QUndoStack m_poseUndo;
    static constexpr int kNoGesture = -2;
    static constexpr int kMouseGesture = -1;
    int m_gestureSource = kNoGesture; ///< what the open gesture edits: the mouse, an angle box or nothing
    int m_gestureBone = -1;
    int m_gesture = 0; ///< the open gesture's number (commands of one gesture merge)
    std::vector<glm::vec3> m_posed;
    std::vector<glm::vec3> m_shown;
    std::vector<std::uint32_t> m_colors;
    SkeletonStageView m_view = SkeletonStageView::Pose;
    int m_selectedBone = -1;
    double m_poseUpdateMs = 0.0;
};

} // namespace trimlab::ui
