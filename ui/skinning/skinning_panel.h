#pragma once
/// \file
/// The Skinning panel (the content of the main window's "Skinning" dock): thesis chapter
/// 4 on the opened animation. The bones are the segments of the segmentation the
/// Segmentation panel shows (setSegmentation(), one bone per segment, in its color), or a
/// given number B of them (the animation segmented anew into exactly B segments with the
/// Segmentation panel's settings, setSegmenterSettings()); the settings form picks
/// LBS/DQS, the chain and the corrections; Fit runs the core's fit on a worker
/// (BackgroundJob on runSkinningFit, core/skinning/skinning_pipeline.h) with a progress
/// bar and Cancel, which keeps the previous fit (job_presenter.h). The result shows E_RMS overall and the stage times, E_RMS per pose as
/// a chart with a dot on the timeline's pose, and the "Show" selector:
/// - Original: the animation's own poses (the timeline plays them);
/// - Approximation: the skinned reconstruction of each pose (shownPose());
/// - Error heat map: each vertex's error at the timeline's pose as vertex colors
///   (displayColors()) on the original poses, on the scale of the largest error of any
///   pose, with a legend naming the pose; it follows the timeline and every bone edit.
///
/// Pose editing (thesis 4.1.3): a bone of the list gets an extra rotation about its
/// centroid and a translation at the timeline's pose (skinning_bone_edit.h); the core
/// propagates it to every later pose without refitting, earlier poses stay bit-identical,
/// and E_RMS is measured again. Every edit is a command on the session's own undo stack
/// (Undo/Redo buttons; Ctrl+Z and Ctrl+Shift+Z — or the platform's other Redo keys —
/// while the focus is inside the panel: the panel claims those keys before any
/// window-wide shortcut, so from here they never reach another undo stack, such as the
/// window's Edit ▸ Undo of the designer's strokes).
///
/// Export glTF… (exportRequested(); the window asks for a file and calls exportGltf())
/// writes the model shown — edits included — as a skinned glTF (or morph targets) on a
/// worker and reports the E_RMS of the file against the original animation.
///
/// The panel computes nothing on the GPU: the window asks it for shownPose() (with
/// shownModel(), which the viewport skins on the GPU where it can, the CPU's pose being the
/// reference and the fallback) and displayColors() whenever displayChanged() is emitted and
/// when the timeline moves.

#include "ui/common/background_job.h"
#include "ui/skinning/skinning_choices.h"

#include "core/animation/animation_segmenter.h"
#include "core/skinning/skinning_model.h"
#include "core/skinning/skinning_pipeline.h"

#include <QString>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace trimlab {
struct BoneEdit;
}

namespace trimlab::ui {

class HeatMapLegend;
class JobPresenter;
class SkinningBoneEditor;
class SkinningErrorChart;
class SkinningSession;
class SkinningSettingsForm;
struct LoadedAnimation;

/// What the viewport shows while a fit exists.
enum class SkinningView { Original, Approximation, ErrorHeatMap };

class SkinningPanel : public QWidget {
    Q_OBJECT
public:
    explicit SkinningPanel(QWidget* parent = nullptr);
    ~SkinningPanel() override;

    /// The animation to fit (nullptr: none, the panel is disabled). Cancels a running fit
    /// and forgets the fit, its edits and the segmentation.
    void setAnimation(std::shared_ptr<const LoadedAnimation> animation);
    /// The segmentation whose segments become the bones — `labeling` (#V labels) with one
    /// color per label — or nullptr (none). Copied; a fit already made keeps its bones.
    void setSegmentation(const VertexLabeling* labeling, const std::vector<WheelColor>* colors);
    /// The segmenter settings a given bone count segments with (the Segmentation panel's).
    void setSegmenterSettings(const SegmenterSettings& settings) { m_segmenterSettings = settings; }
    /// The pose the timeline shows: the chart's marker and the pose edits apply to.
    void setCurrentPose(int pose);

    void setChoices(const SkinningChoices& choices);
    [[nodiscard]] SkinningChoices choices() const;

    /// Fit's click: fits on a worker (no-op while running, without an animation, or — for
    /// bones from the segmentation — without a segmentation of its vertices).
    void fit();
    /// Cancels a running fit; the previous fit (if any) stays.
    void cancel();
    [[nodiscard]] bool isRunning() const;

    /// The fit and its edits (nullptr before the first fit of this animation).
    [[nodiscard]] SkinningSession* session() const { return m_session.get(); }
    [[nodiscard]] BackgroundJobBase* fitTask() const { return m_job; }
    [[nodiscard]] BackgroundJobBase* exportTask() const { return m_exportJob; }

    /// Writes the model shown to `path` (.gltf or .glb) on a worker, its keyframes `fps`
    /// apart; exportFinished() or exportFailed() follows. No-op without a fit or while an
    /// export runs.
    void exportGltf(const QString& path, double fps);
    [[nodiscard]] SkinningErrorChart* errorChart() const { return m_chart; }

    void setView(SkinningView view);
    [[nodiscard]] SkinningView view() const { return m_view; }
    /// The positions to show at `pose` instead of the original (the approximation), or
    /// nullopt to show the original pose.
    [[nodiscard]] std::optional<std::vector<glm::vec3>> shownPose(int pose) const;
    /// The model whose pose shownPose() returns (edits included), or nullptr when it
    /// returns nullopt.
    [[nodiscard]] std::shared_ptr<const SkinningModel> shownModel(int pose) const;
    /// #V RGBA8 colors of the error heat map while it is shown, else empty.
    [[nodiscard]] const std::vector<std::uint32_t>& displayColors() const { return m_displayColors; }

    /// E_RMS as the panel's labels write it.
    [[nodiscard]] static QString formatERms(double eRms);

signals:
    /// shownPose() or displayColors() changed: the window shows them again.
    void displayChanged();
    /// A fit finished and session() changed.
    void resultChanged();
    /// Export glTF… was pressed: the window asks for a file and calls exportGltf().
    void exportRequested();
    /// `path` was written; `eRms` is the file's E_RMS against the original animation,
    /// `kind` what it holds (skinExportKindName).
    void exportFinished(const QString& path, double eRms, const QString& kind);
    void exportFailed(const QString& path, const QString& message);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    QWidget* createFitRow();
    QWidget* createResultGroup();
    QWidget* createEditGroup();
    QWidget* createExportRow();
    void connectJob();
    void connectExportJob();
    void onFormChanged();
    void onFitSucceeded();
    void onFitEnded(const QString& status);
    void onModelChanged();
    void onApplyRequested(int bone, const BoneEdit& edit);
    void onViewChosen();
    void showResult();
    void refreshDisplay();
    /// The pose the heat map shows: the timeline's, within the fit's poses.
    [[nodiscard]] std::size_t heatMapPose() const;
    /// Each vertex's distance from the original at heatMapPose() (empty without a fit).
    [[nodiscard]] std::vector<double> heatMapErrors() const;
    void updateControls();
    void updateEditPose();
    void setStatus(const QString& text);
    [[nodiscard]] QString readyStatus() const;
    [[nodiscard]] bool hasUsableSegmentation() const;
    [[nodiscard]] bool canFit() const;

    SkinningSettingsForm* m_form = nullptr;
    QPushButton* m_fit = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_error = nullptr;
    QLabel* m_times = nullptr;
    SkinningErrorChart* m_chart = nullptr;
    QComboBox* m_viewBox = nullptr;
    HeatMapLegend* m_legend = nullptr;
    QWidget* m_editGroup = nullptr;
    SkinningBoneEditor* m_editor = nullptr;
    QPushButton* m_export = nullptr;
    QCheckBox* m_morphTargets = nullptr;
    QComboBox* m_interpolation = nullptr; ///< the skin's keyframes: linear or step

    /// What an export reports: the file's E_RMS against the original, and what it holds.
    struct ExportOutcome {
        double eRms = 0.0;
        QString kind;
    };

    BackgroundJob<std::shared_ptr<const SkinningFit>>* m_job = nullptr;
    BackgroundJob<ExportOutcome>* m_exportJob = nullptr;
    JobPresenter* m_presenter = nullptr;
    std::shared_ptr<const LoadedAnimation> m_animation;
    std::shared_ptr<const LoadedAnimation> m_fitAnimation; ///< what the running fit was started on
    std::optional<VertexLabeling> m_segmentation;
    std::vector<WheelColor> m_segmentColors;
    SegmenterSettings m_segmenterSettings;
    QString m_exportPath; ///< the running export's file
    std::unique_ptr<SkinningSession> m_session;
    SkinningView m_view = SkinningView::Original;
    std::vector<std::uint32_t> m_displayColors;
    int m_currentPose = 0;
};

} // namespace trimlab::ui
