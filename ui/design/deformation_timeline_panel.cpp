#include "ui/design/deformation_timeline_panel.h"

#include "ui/design/deformation_track.h"

#include "ui/common/frame_slider.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <array>

namespace trimlab::ui {

namespace {

constexpr std::array kRules = {DynamicRule::Confluent, DynamicRule::HomogeneousConfluent,
                               DynamicRule::ConstructiveAdditive, DynamicRule::ConstructiveSubtractive,
                               DynamicRule::ConstructiveIntersection};

QString latin1(std::string_view text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

} // namespace

DeformationTimelinePanel::DeformationTimelinePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("deformationTimelinePanel"));
    createControls();
    connect(&m_timer, &QTimer::timeout, this, &DeformationTimelinePanel::advance);
    setFps(12);
    setHistory(nullptr, 0);
}

void DeformationTimelinePanel::createControls()
{
    auto* layout = new QVBoxLayout(this);
    m_track = new DeformationTrack(this);
    layout->addWidget(m_track);
    auto* row = new QHBoxLayout;
    layout->addLayout(row);
    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("deformationPlayButton"));
    row->addWidget(m_play);
    m_slider = new FrameSlider(this);
    m_slider->setObjectName(QStringLiteral("deformationSlider"));
    m_slider->setToolTip(tr("Frame: %1").arg(FrameSlider::inputHelp()));
    row->addWidget(m_slider, 1);
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName(QStringLiteral("deformationFrameLabel"));
    m_frameLabel->setMinimumWidth(m_frameLabel->fontMetrics().horizontalAdvance(QStringLiteral("Frame 0000 / 0000")));
    row->addWidget(m_frameLabel);
    m_fps = new QSpinBox(this);
    m_fps->setObjectName(QStringLiteral("deformationFpsSpinBox"));
    m_fps->setRange(kMinFps, kMaxFps);
    m_fps->setSuffix(tr(" fps"));
    row->addWidget(m_fps);
    m_rule = new QComboBox(this);
    m_rule->setObjectName(QStringLiteral("deformationRuleComboBox"));
    for (const DynamicRule rule : kRules)
        m_rule->addItem(latin1(dynamicRuleDisplayName(rule)), latin1(dynamicRuleName(rule)));
    m_rule->setToolTip(tr("The dynamic rule of the current set: how space the set's strokes swept is classified "
                          "(thesis 8.1.1)."));
    row->addWidget(m_rule);
    m_newSet = new QToolButton(this);
    m_newSet->setObjectName(QStringLiteral("newSetButton"));
    m_newSet->setText(tr("New set"));
    m_newSet->setToolTip(tr("Start a new set of concurrent disjoint deformations whose reference is the last frame "
                            "(N)."));
    row->addWidget(m_newSet);
    connect(m_track, &DeformationTrack::frameClicked, this, &DeformationTimelinePanel::chooseFrame);
    connect(m_slider, &QSlider::valueChanged, this, &DeformationTimelinePanel::chooseFrame);
    connect(m_play, &QToolButton::clicked, this, &DeformationTimelinePanel::togglePlaying);
    // As a click on Play: nothing while the button is disabled (fewer than two frames).
    connect(m_slider, &FrameSlider::playToggleRequested, m_play, &QToolButton::click);
    connect(m_fps, &QSpinBox::valueChanged, this, [this](int fps) {
        m_timer.setInterval(1000 / fps);
        emit fpsChanged(fps);
    });
    connect(m_rule, &QComboBox::activated, this, [this] { emit ruleChosen(chosenRule()); });
    connect(m_newSet, &QToolButton::clicked, this, &DeformationTimelinePanel::requestNewSet);
    updatePlayButton();
}

void DeformationTimelinePanel::setHistory(const timeline::Timeline* history, int shownFrame)
{
    const bool has = history && history->frameCount() > 0;
    setEnabled(has);
    const int frames = has ? history->frameCount() : 0;
    m_track->setHistory(frames, has ? history->sets() : std::vector<timeline::DeformationSet>{}, shownFrame);
    {
        const QSignalBlocker blocker(m_slider);
        m_slider->setRange(0, std::max(frames - 1, 0));
        m_slider->setValue(shownFrame);
    }
    if (has && !history->sets().empty()) {
        const QSignalBlocker blocker(m_rule);
        m_rule->setCurrentIndex(m_rule->findData(latin1(dynamicRuleName(history->sets().back().rule))));
    }
    if (!has)
        pause();
    updateFrameLabel();
}

void DeformationTimelinePanel::setShownFrame(int frame)
{
    const QSignalBlocker blocker(m_slider);
    m_slider->setValue(frame);
    m_track->setShownFrame(m_slider->value());
    updateFrameLabel();
}

int DeformationTimelinePanel::shownFrame() const
{
    return m_slider->value();
}

void DeformationTimelinePanel::play()
{
    if (m_slider->maximum() == 0)
        return;
    if (m_slider->value() == m_slider->maximum())
        chooseFrame(0); // replay from the start
    m_timer.start(1000 / fps());
    updatePlayButton();
}

void DeformationTimelinePanel::pause()
{
    m_timer.stop();
    updatePlayButton();
}

int DeformationTimelinePanel::fps() const
{
    return m_fps->value();
}

void DeformationTimelinePanel::setFps(int fps)
{
    const QSignalBlocker blocker(m_fps);
    m_fps->setValue(std::clamp(fps, kMinFps, kMaxFps));
    m_timer.setInterval(1000 / m_fps->value());
}

DynamicRule DeformationTimelinePanel::chosenRule() const
{
    return parseDynamicRule(m_rule->currentData().toString().toStdString()).value_or(DynamicRule::Confluent);
}

void DeformationTimelinePanel::requestNewSet()
{
    if (isEnabled())
        emit newSetRequested(chosenRule());
}

// Playback stops at the last frame: that is where the brush works.
void DeformationTimelinePanel::advance()
{
    if (m_slider->value() >= m_slider->maximum()) {
        pause();
        return;
    }
    chooseFrame(m_slider->value() + 1);
}

void DeformationTimelinePanel::togglePlaying()
{
    if (isPlaying())
        pause();
    else
        play();
}

void DeformationTimelinePanel::chooseFrame(int frame)
{
    setShownFrame(frame);
    emit frameChosen(m_slider->value());
}

void DeformationTimelinePanel::updateFrameLabel()
{
    m_frameLabel->setText(tr("Frame %1 / %2").arg(m_slider->value()).arg(m_slider->maximum()));
}

void DeformationTimelinePanel::updatePlayButton()
{
    m_play->setIcon(style()->standardIcon(isPlaying() ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setToolTip(isPlaying() ? tr("Pause") : tr("Play the frames"));
}

} // namespace trimlab::ui
