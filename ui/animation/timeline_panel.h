#pragma once
/// \file
/// The Timeline (the content of the main window's "Timeline" dock): a pose slider
/// 0 … k−1 with the pose's number and name, play/pause, frames per second and loop.
/// Playback runs on a QTimer in the UI thread, one pose per tick, and never blocks;
/// playing or scrubbing emits poseChanged(), which the window turns into a viewport
/// pose. Keys on the slider: ←/→ one pose, PgUp/PgDn ten, Home/End first/last.

#include <QStringList>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;

namespace trimlab::ui {

class TimelinePanel : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMinFps = 1;
    static constexpr int kMaxFps = 120;

    explicit TimelinePanel(QWidget* parent = nullptr);

    /// Shows the poses named `names` (one per pose), at pose 0, paused. No names: the
    /// controls are disabled ("no animation").
    void setPoses(const QStringList& names);
    /// Goes to `pose` (clamped) and emits poseChanged() if it changed.
    void setPose(int pose);
    [[nodiscard]] int pose() const;
    [[nodiscard]] int poseCount() const { return int(m_names.size()); }

    void play();
    void pause();
    [[nodiscard]] bool isPlaying() const { return m_timer.isActive(); }

    /// Frames per second (clamped to kMinFps … kMaxFps) and looping, without emitting
    /// playbackChoicesChanged().
    void setPlaybackChoices(int fps, bool loop);
    [[nodiscard]] int fps() const;
    [[nodiscard]] bool loops() const;

signals:
    /// The shown pose changed (by playback, the slider, or setPose()).
    void poseChanged(int pose);
    /// Playback started or stopped.
    void playingChanged(bool playing);
    /// The user changed fps or loop.
    void playbackChoicesChanged();

private:
    void createControls();
    void advance();
    void togglePlaying();
    void onSliderMoved(int pose);
    void updatePoseLabel();
    void updatePlayButton();
    void applyFps();

    QSlider* m_slider = nullptr;
    QLabel* m_poseLabel = nullptr;
    QToolButton* m_play = nullptr;
    QSpinBox* m_fps = nullptr;
    QCheckBox* m_loop = nullptr;
    QTimer m_timer;
    QStringList m_names;
};

} // namespace trimlab::ui
