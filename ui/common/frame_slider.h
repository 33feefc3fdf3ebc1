#pragma once
/// \file
/// The slider of a timeline (poses of an animation, frames of a deformation history), with
/// the habits of Blender's and every video player's timeline: a click on the groove goes
/// to the frame under the cursor and keeps dragging from there (a plain QSlider steps one
/// page towards the click, which on a history shorter than a page lands on its first or
/// last frame), and Space asks the timeline to play or pause. ←/→, PgUp/PgDn and Home/End
/// stay QSlider's.

#include <QSlider>

namespace trimlab::ui {

class FrameSlider : public QSlider {
    Q_OBJECT
public:
    explicit FrameSlider(QWidget* parent = nullptr);

    /// What the mouse and the keys do on a timeline slider, for tooltips and the
    /// Keyboard Shortcuts dialog.
    [[nodiscard]] static QString inputHelp();

signals:
    /// Space was pressed while the slider had the focus.
    void playToggleRequested();

protected:
    void keyPressEvent(QKeyEvent* event) override;
};

} // namespace trimlab::ui
