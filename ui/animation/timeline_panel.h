#pragma once
/// \file
/// The Timeline (the content of the main window's "Timeline" dock): a pose slider
/// 0 … k−1 with the pose's number and name, play/pause, frames per second and loop.
/// Playback runs on a QTimer in the UI thread and never blocks. It keeps time: each tick
/// shows the pose the clock has reached since Play (pose = start + elapsed × fps), so a
/// renderer slower than the rate drops poses instead of slowing the animation down, and
/// the rate label says how many poses per second were actually shown. Playing or
/// scrubbing emits poseChanged(), which the window turns into a viewport pose. A click on
/// the slider goes to the pose under the cursor; keys on it: ←/→ one pose, PgUp/PgDn ten,
/// Home/End first/last, Space play/pause (ui/common/frame_slider.h).

#include <QElapsedTimer>
#include <QStringList>
#include <QTimer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QSpinBox;
class QToolButton;

namespace trimlab::ui {

class FrameSlider;

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
    /// Poses shown per second since Play (0 before the first second of playing).
    [[nodiscard]] double achievedFps() const { return m_achievedFps; }

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
    void restartClock();
    void updateRateLabel();

    FrameSlider* m_slider = nullptr;
    QLabel* m_poseLabel = nullptr;
    QLabel* m_rateLabel = nullptr;
    QToolButton* m_play = nullptr;
    QSpinBox* m_fps = nullptr;
    QCheckBox* m_loop = nullptr;
    QTimer m_timer;
    QElapsedTimer m_playStart; ///< since Play: the rate shown
    QElapsedTimer m_clock;     ///< since Play, or since the fps changed while playing
    int m_clockStartPose = 0;  ///< the pose shown when m_clock started
    qint64 m_clockStep = 0;    ///< poses the clock has counted since it started, the last one shown
    int m_shownSinceStart = 0; ///< poses shown since Play
    double m_achievedFps = 0.0;
    bool m_advancing = false; ///< advance() is moving the slider (not the user)
    QStringList m_names;
};

} // namespace trimlab::ui
