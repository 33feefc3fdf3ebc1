#pragma once
/// \file
/// The Deformation timeline (content of the "Deformation timeline" dock; the animation
/// Timeline is a different dock): the track of frames and sets (deformation_track.h), a
/// scrub slider, play/pause with frames per second, and the sets' rules: "New set" (N)
/// starts a set of concurrent disjoint deformations with the chosen rule, and choosing a
/// rule while strokes are being made changes the current (last) set's rule. Both are
/// requests: the window turns them into undoable commands. A click on the slider goes to
/// the frame under the cursor; keys on it: ←/→ one frame, Home/End first/last, Space
/// play/pause (ui/common/frame_slider.h).

#include "core/timeline/timeline.h"

#include <QTimer>
#include <QWidget>

class QComboBox;
class QLabel;
class QSpinBox;
class QToolButton;

namespace trimlab::ui {

class DeformationTrack;
class FrameSlider;

class DeformationTimelinePanel : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMinFps = 1;
    static constexpr int kMaxFps = 60;

    explicit DeformationTimelinePanel(QWidget* parent = nullptr);

    /// Shows `history` (nullptr: no history, controls disabled) at `shownFrame`, without
    /// emitting frameChosen(). The rule chooser shows the last set's rule.
    void setHistory(const timeline::Timeline* history, int shownFrame);
    /// Moves the slider and the track's cursor (no frameChosen()).
    void setShownFrame(int frame);
    [[nodiscard]] int shownFrame() const;

    void play();
    void pause();
    [[nodiscard]] bool isPlaying() const { return m_timer.isActive(); }
    [[nodiscard]] int fps() const;
    /// Clamped to kMinFps … kMaxFps; no fpsChanged().
    void setFps(int fps);

    /// The rule the chooser shows.
    [[nodiscard]] DynamicRule chosenRule() const;
    /// What "New set" and its shortcut do: emits newSetRequested(chosenRule()).
    void requestNewSet();

    [[nodiscard]] DeformationTrack* track() const { return m_track; }

signals:
    /// The user chose frame `frame` (slider, track, playback).
    void frameChosen(int frame);
    void newSetRequested(DynamicRule rule);
    /// The user chose `rule` for the current set.
    void ruleChosen(DynamicRule rule);
    void fpsChanged(int fps);

private:
    void createControls();
    void advance();
    void togglePlaying();
    void chooseFrame(int frame);
    void updateFrameLabel();
    void updatePlayButton();

    DeformationTrack* m_track = nullptr;
    FrameSlider* m_slider = nullptr;
    QLabel* m_frameLabel = nullptr;
    QToolButton* m_play = nullptr;
    QSpinBox* m_fps = nullptr;
    QComboBox* m_rule = nullptr;
    QToolButton* m_newSet = nullptr;
    QTimer m_timer;
};

} // namespace trimlab::ui
