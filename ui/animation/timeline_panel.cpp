#include "ui/animation/timeline_panel.h"

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
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName(QStringLiteral("poseSlider"));
    m_slider->setPageStep(kPageStep);
    m_slider->setToolTip(tr("Pose: ←/→ one pose, PgUp/PgDn ten, Home/End first/last"));
    connect(m_slider, &QSlider::valueChanged, this, &TimelinePanel::onSliderMoved);
    m_poseLabel = new QLabel;
    m_poseLabel->setObjectName(QStringLiteral("poseLabel"));
    m_poseLabel->setMinimumWidth(160);
    m_fps = new QSpinBox;
    m_fps->setObjectName(QStringLiteral("fpsSpinBox"));
    m_fps->setRange(kMinFps, kMaxFps);
    m_fps->setValue(kDefaultFps);
    m_fps->setSuffix(tr(" fps"));
    connect(m_fps, &QSpinBox::valueChanged, this, [this] {
        applyFps();
        emit playbackChoicesChanged();
    });
    m_loop = new QCheckBox(tr("Loop"));
    m_loop->setObjectName(QStringLiteral("loopCheckBox"));
    m_loop->setChecked(true);
    connect(m_loop, &QCheckBox::toggled, this, &TimelinePanel::playbackChoicesChanged);

    auto* layout = new QHBoxLayout(this);
    layout->addWidget(m_play);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_poseLabel);
    layout->addWidget(m_fps);
    layout->addWidget(m_loop);
}

void TimelinePanel::setPoses(const QStringList& names)
{
    pause();
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

void TimelinePanel::advance()
{
    const int next = pose() + 1;
    if (next < poseCount()) {
        setPose(next);
        return;
    }
    if (loops())
        setPose(0);
    else
        pause();
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
}

void TimelinePanel::onSliderMoved(int pose)
{
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
