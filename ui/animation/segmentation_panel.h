#pragma once
/// \file
/// The Segmentation panel (the content of the main window's "Segmentation" dock): thesis
/// chapter 3 on the opened animation. The settings form chooses what to compute;
/// Run computes it on a worker (BackgroundJob on runSegmentation,
/// core/animation/segmentation_run.h) with a progress bar and Cancel, which keeps the
/// previous result (job_presenter.h); the h slider re-cleans the finished
/// segmentation on the UI thread at every step (segment(h) + recoloring + packing take
/// 2–5 ms on the 10k–42k-vertex samba and elephant) and recolors it from the previous
/// h's colors (segment_colors.h) while the label shows the live segment count; "Color
/// by segment" puts the colors on the animation.
///
/// Modes: Global shows segment(h); Real-time makes Run a "Stream poses" run
/// (segment_stream.h) that starts from the first pose, asks the window to play the
/// timeline (streamStarted()) and appends each pose as the timeline reaches it, showing
/// the segmentation so far and the poses processed; once every pose is in, the stream's
/// segmenter becomes the result (equal to a global run). Variable shows, at each pose of
/// the timeline, that pose's partition joined with the next (setCurrentPose()), with
/// colors carried from pose to pose; h does not apply there.
///
/// The panel computes nothing on the GPU: the window passes displayColors() to the
/// viewport when displayColorsChanged() is emitted.

#include "core/animation/segment_colors.h"
#include "core/animation/segmentation_run.h"
#include "ui/animation/segmentation_choices.h"
#include "ui/common/background_job.h"

#include <QString>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;

namespace trimlab::ui {

class JobPresenter;
class SegmentStream;
class SegmentationSettingsForm;
struct LoadedAnimation;
struct StreamStep;

class SegmentationPanel : public QWidget {
    Q_OBJECT
public:
    /// Steps of the h slider over [0, 1].
    static constexpr int kHSteps = 1000;

    explicit SegmentationPanel(QWidget* parent = nullptr);
    ~SegmentationPanel() override;

    /// The animation to segment (nullptr: none, the panel is disabled). Stops a running
    /// job or stream and forgets the previous result.
    void setAnimation(std::shared_ptr<const LoadedAnimation> animation);
    /// The pose the timeline shows (variable mode shows its segmentation; a stream may
    /// append it).
    void setCurrentPose(int pose);

    /// Shows `choices` (h and mode included) without emitting choicesChanged().
    void setChoices(const SegmentationChoices& choices);
    [[nodiscard]] const SegmentationChoices& choices() const { return m_choices; }

    /// What Run does in the current mode (the Run button's click).
    void run();
    /// Cancels a running job (the previous result stays) or stops a stream.
    void cancel();
    /// Writes the shown global segmentation (and in variable mode the per-pose one) as
    /// .json, .csv or .gltf by the extension of `path` (segmentation_record.h). Returns
    /// false with the reason in `error` when there is no result or writing fails.
    bool exportSegmentation(const QString& path, QString* error = nullptr);

    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] std::shared_ptr<const SegmentationResult> result() const { return m_result; }
    /// The labeling shown now (nullptr when none) and its colors (one per label).
    [[nodiscard]] const VertexLabeling* shownLabeling() const;
    [[nodiscard]] const std::vector<WheelColor>* shownColors() const;
    /// #V RGBA8 colors for the viewport; empty when color by segment is off or nothing is
    /// segmented.
    [[nodiscard]] const std::vector<std::uint32_t>& displayColors() const { return m_displayColors; }
    /// The task Run uses (its progressed() comes from the worker thread).
    [[nodiscard]] BackgroundJobBase* runTask() const { return m_job; }
    [[nodiscard]] SegmentStream* stream() const { return m_stream; }
    /// Milliseconds of the last h change: segment(h), and recoloring + packing.
    [[nodiscard]] double lastCleaningMs() const { return m_cleaningMs; }
    [[nodiscard]] double lastColoringMs() const { return m_coloringMs; }

signals:
    void displayColorsChanged();
    /// The user changed a choice (to be saved).
    void choicesChanged();
    /// A real-time stream began at pose 0: the timeline should go there and play.
    void streamStarted();
    /// Export… was pressed: the window asks for a file and calls exportSegmentation().
    void exportRequested();
    /// A run or stream finished and result() changed.
    void resultChanged();

private:
    QWidget* createRunRow();
    QWidget* createCleaningGroup();
    void connectJobs();
    void onFormChanged();
    void onHSliderMoved(int value);
    void applyH();
    void onColorToggled(bool on);
    void startRun();
    void startStream();
    void onRunSucceeded();
    void onRunEnded(const QString& status);
    void onStreamStep(const StreamStep& step);
    void onStreamFinished(std::shared_ptr<const SegmentationResult> result);
    void adoptResult(std::shared_ptr<const SegmentationResult> result, const SegmenterSettings& settings);
    void refreshDisplay();
    void updateControls();
    void updateCountLabel();
    void showTimes(const SegmentationTimes& times, std::optional<double> cleaningMs);
    void setStatus(const QString& text);
    [[nodiscard]] QString readyStatus() const;
    /// The Run button's label for the mode chosen ("Stream poses" in real-time mode).
    [[nodiscard]] QString runLabel() const;
    [[nodiscard]] bool settingsMatchResult() const;

    /// What the viewport shows: a labeling and one color per label (both null: nothing).
    struct Shown {
        const VertexLabeling* labeling = nullptr;
        const std::vector<WheelColor>* colors = nullptr;
    };
    [[nodiscard]] Shown shown() const;

    SegmentationSettingsForm* m_form = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QSlider* m_hSlider = nullptr;
    QLabel* m_hLabel = nullptr;
    QLabel* m_count = nullptr;
    QCheckBox* m_colorBySegment = nullptr;
    QLabel* m_times = nullptr;
    QPushButton* m_export = nullptr;

    BackgroundJob<std::shared_ptr<const SegmentationResult>>* m_job = nullptr;
    JobPresenter* m_presenter = nullptr;
    SegmentStream* m_stream = nullptr;
    std::shared_ptr<const LoadedAnimation> m_animation;
    std::shared_ptr<const LoadedAnimation> m_runAnimation; ///< what the last Run was started on
    SegmentationChoices m_choices;
    /// The settings the running job or stream runs with.
    SegmenterSettings m_pendingSettings;
    std::shared_ptr<const SegmentationResult> m_result;
    SegmenterSettings m_resultSettings;
    SegmentColors m_cleaned;     ///< the result's segment(h), colored
    SegmentColors m_streamShown; ///< the last stream step
    std::vector<std::uint32_t> m_displayColors;
    int m_currentPose = 0;
    double m_cleaningMs = 0.0;
    double m_coloringMs = 0.0;
};

} // namespace trimlab::ui
