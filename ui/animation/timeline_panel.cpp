#include "ui/animation/timeline_panel.h"

#include "ui/common/frame_slider.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>

#include <algorithm>

namespace trimlab::ui {

namespace {

constexpr int kDefaultFps = 24;
constexpr int kPageStep = 10;

} // namespace

TimelinePanel::TimelinePanel(QWidget* parent) : QWidget(parent)
{
    createControls();
    connect(&m_timer, &QTimer::timeout, this, &TimelinePanel::advance);
    applyFps();
    setPoses({});
}

void TimelinePanel::createControls()
{
    m_play = new QToolButton;
    m_play->setObjectName(QStringLiteral("playButton"));
    m_play->setToolTip(tr("Play or pause the animation"));
    connect(m_play, &QToolButton::clicked, this, &TimelinePanel::togglePlaying);
    m_slider = new FrameSlider;
    m_slider->setObjectName(QStringLiteral("poseSlider"));
    m_slider->setPageStep(kPageStep);
    m_slider->setToolTip(tr("Pose: %1").arg(FrameSlider::inputHelp()));
    connect(m_slider, &QSlider::valueChanged, this, &TimelinePanel::onSliderMoved);
    // As a click on Play: nothing while the button is disabled (fewer than two frames).
    connect(m_slider, &FrameSlider::playToggleRequested, m_play, &QToolButton::click);
    m_poseLabel = new QLabel;
    m_poseLabel->setObjectName(QStringLiteral("poseLabel"));
    m_poseLabel->setMinimumWidth(160);
    m_fps = new QSpinBox;
    m_fps->setObjectName(QStringLiteral("fpsSpinBox"));
    m_fps->setRange(kMinFps, kMaxFps);
    m_fps->setValue(kDefaultFps);
    m_fps->setSuffix(tr(" fps"));
    m_fps->setToolTip(tr("Poses per second to play. A slow view drops poses to keep this rate; the label beside "
                         "says how many it showed."));
    connect(m_fps, &QSpinBox::valueChanged, this, [this] {
        applyFps();
        emit playbackChoicesChanged();
    });
    m_rateLabel = new QLabel;
    m_rateLabel->setObjectName(QStringLiteral("playbackRateLabel"));
    m_rateLabel->setToolTip(tr("Poses per second shown while playing; fewer than asked means poses were dropped to "
                               "keep time"));
    m_loop = new QCheckBox(tr("Loop"));
    m_loop->setObjectName(QStringLiteral("loopCheckBox"));
    m_loop->setChecked(true);
    connect(m_loop, &QCheckBox::toggled, this, &TimelinePanel::playbackChoicesChanged);

    auto* layout = new QHBoxLayout(this);
    layout->addWidget(m_play);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_poseLabel);
    layout->addWidget(m_fps);
    layout->addWidget(m_rateLabel);
    layout->addWidget(m_loop);
}

void TimelinePanel::setPoses(const QStringList& names)
{
    pause();
    m_rateLabel->clear();
    m_names = names;
    {
        const QSignalBlocker blocker(m_slider);
        m_slider->setRange(0, std::max(0, poseCount() - 1));
        m_slider->setValue(0);
    }
    const bool any = !m_names.isEmpty();
    m_slider->setEnabled(any);
    m_play->setEnabled(any && poseCount() > 1);
    updatePoseLabel();
    updatePlayButton();
}

void TimelinePanel::setPose(int pose)
{
    m_slider->setValue(std::clamp(pose, 0, std::max(0, poseCount() - 1)));
}

int TimelinePanel::pose() const
{
    return m_slider->value();
}

void TimelinePanel::play()
{
    if (poseCount() < 2 || isPlaying())
        return;
    if (!loops() && pose() == poseCount() - 1)
        setPose(0); // play from the start again
    m_shownSinceStart = 0;
    m_achievedFps = 0.0;
    m_rateLabel->clear();
    m_playStart.start();
    restartClock();
    m_timer.start();
    updatePlayButton();
    emit playingChanged(true);
}

void TimelinePanel::pause()
{
    if (!isPlaying())
        return;
    m_timer.stop();
    updatePlayButton();
    emit playingChanged(false);
}

void TimelinePanel::togglePlaying()
{
    if (isPlaying())
        pause();
    else
        play();
}

// The pose the clock has reached, not the next one: when frames take longer than 1/fps
// the poses in between are dropped and the animation keeps its duration.
void TimelinePanel::advance()
{
    const qint64 step = m_clock.elapsed() * qint64(fps()) / 1000;
    if (step == m_clockStep)
        return; // that pose is shown already
    m_clockStep = step;
    const qint64 target = qint64(m_clockStartPose) + step;
    const int count = poseCount();
    m_advancing = true;
    if (target >= count && !loops()) {
        setPose(count - 1);
        pause();
    } else {
        setPose(int(target % count));
    }
    m_advancing = false;
    ++m_shownSinceStart;
    updateRateLabel();
}

void TimelinePanel::restartClock()
{
    m_clock.start();
    m_clockStartPose = pose();
    m_clockStep = 0;
}

// Over the whole play, once a second has passed; the last figure stays after a pause.
void TimelinePanel::updateRateLabel()
{
    const qint64 elapsed = m_playStart.elapsed();
    if (elapsed < 1000)
        return;
    m_achievedFps = 1000.0 * m_shownSinceStart / double(elapsed);
    m_rateLabel->setText(tr("%1 fps shown").arg(m_achievedFps, 0, 'f', 1));
}

void TimelinePanel::setPlaybackChoices(int fps, bool loop)
{
    const QSignalBlocker fpsBlocker(m_fps);
    const QSignalBlocker loopBlocker(m_loop);
    m_fps->setValue(std::clamp(fps, kMinFps, kMaxFps));
    m_loop->setChecked(loop);
    applyFps();
}

int TimelinePanel::fps() const
{
    return m_fps->value();
}

bool TimelinePanel::loops() const
{
    return m_loop->isChecked();
}

void TimelinePanel::applyFps()
{
    m_timer.setInterval(std::max(1, 1000 / fps()));
    if (isPlaying())
        restartClock(); // the new rate counts from the pose shown now
}

void TimelinePanel::onSliderMoved(int pose)
{
    if (isPlaying() && !m_advancing)
        restartClock(); // scrubbed while playing: play on from here
    updatePoseLabel();
    emit poseChanged(pose);
}

void TimelinePanel::updatePoseLabel()
{
    if (m_names.isEmpty()) {
        m_poseLabel->setText(tr("No animation"));
        return;
    }
    const int index = pose();
    // Pose indices as the core and the exports number them: 0 … k−1.
    m_poseLabel->setText(tr("pose %1 / %2  %3").arg(index).arg(poseCount() - 1).arg(m_names.value(index)));
}

void TimelinePanel::updatePlayButton()
{
    const bool playing = isPlaying();
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setText(playing ? tr("Pause") : tr("Play"));
}

} // namespace trimlab::ui
