#include "ui/animation/segmentation_panel.h"

#include "ui/common/parameter_form.h"
#include "ui/common/run_cancel_row.h"

#include "ui/common/job_presenter.h"
#include "ui/common/loaded_animation.h"
#include "ui/animation/segment_stream.h"
#include "ui/animation/segmentation_settings_form.h"

#include "core/animation/segmentation_record.h"

#include <QCheckBox>
#include <QElapsedTimer>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include <cmath>

namespace trimlab::ui {

namespace {

double elapsedMs(const QElapsedTimer& timer)
{
    return double(timer.nsecsElapsed()) * 1e-6;
}

QString milliseconds(double ms)
{
    return QStringLiteral("%1 ms").arg(ms, 0, 'f', ms < 10.0 ? 2 : 1);
}

} // namespace

SegmentationPanel::SegmentationPanel(QWidget* parent) : QWidget(parent)
{
    m_job = new BackgroundJob<std::shared_ptr<const SegmentationResult>>(this);
    m_stream = new SegmentStream(this);
    m_form = new SegmentationSettingsForm;
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("segmentationProgressBar"));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("segmentationStatusLabel"));
    m_status->setWordWrap(true);
    m_times = new QLabel;
    m_times->setObjectName(QStringLiteral("segmentationTimesLabel"));
    m_times->setWordWrap(true);
    m_export = new QPushButton(tr("Export…"));
    m_export->setObjectName(QStringLiteral("exportSegmentationButton"));
    m_export->setToolTip(tr("Per-vertex labels as JSON or CSV, or the rest pose as glTF with the segment colors "
                            "(COLOR_0) and labels (_SEGMENT)"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_form);
    layout->addWidget(createRunRow());
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(createCleaningGroup());
    layout->addWidget(m_times);
    layout->addWidget(m_export);
    layout->addStretch();
    connect(m_form, &SegmentationSettingsForm::changed, this, &SegmentationPanel::onFormChanged);
    connect(m_export, &QPushButton::clicked, this, &SegmentationPanel::exportRequested);
    connectJobs();
    setChoices(m_choices);
    setAnimation(nullptr);
}

SegmentationPanel::~SegmentationPanel() = default;

QWidget* SegmentationPanel::createRunRow()
{
    m_run = new QPushButton(tr("Run"));
    m_run->setObjectName(QStringLiteral("runSegmentationButton"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setObjectName(QStringLiteral("cancelSegmentationButton"));
    connect(m_run, &QPushButton::clicked, this, &SegmentationPanel::run);
    connect(m_cancel, &QPushButton::clicked, this, &SegmentationPanel::cancel);
    return runCancelRow(m_run, m_cancel);
}

QWidget* SegmentationPanel::createCleaningGroup()
{
    auto* group = new QGroupBox(tr("Cleaning"));
    m_hSlider = new QSlider(Qt::Horizontal);
    m_hSlider->setObjectName(QStringLiteral("hSlider"));
    m_hSlider->setRange(int(std::lround(segmentation_parameters::kH.min * kHSteps)),
                        int(std::lround(segmentation_parameters::kH.max * kHSteps)));
    m_hSlider->setSingleStep(1);
    m_hSlider->setPageStep(kHSteps / 20);
    m_hSlider->setToolTip(parameterToolTip(segmentation_parameters::kH));
    m_hLabel = new QLabel;
    m_hLabel->setObjectName(QStringLiteral("hLabel"));
    m_count = new QLabel;
    m_count->setObjectName(QStringLiteral("segmentCountLabel"));
    m_count->setWordWrap(true);
    m_colorBySegment =
        parameterCheckBox(segmentation_parameters::kColorBySegment, tr("Color by segment"), "colorBySegmentCheckBox");
    connect(m_hSlider, &QSlider::valueChanged, this, &SegmentationPanel::onHSliderMoved);
    connect(m_colorBySegment, &QCheckBox::toggled, this, &SegmentationPanel::onColorToggled);
    auto* hRow = new QHBoxLayout;
    hRow->addWidget(m_hSlider, 1);
    hRow->addWidget(m_hLabel);
    auto* layout = new QVBoxLayout(group);
    layout->addLayout(hRow);
    layout->addWidget(m_count);
    layout->addWidget(m_colorBySegment);
    return group;
}

void SegmentationPanel::connectJobs()
{
    m_presenter =
        new JobPresenter(m_job, {m_run, m_cancel, m_progress, m_status}, JobPresenter::ProgressText::Count, this);
    connect(m_job, &BackgroundJobBase::succeeded, this, &SegmentationPanel::onRunSucceeded);
    connect(m_job, &BackgroundJobBase::canceled, this, [this] {
        onRunEnded(m_runAnimation == m_animation ? tr("Canceled; the previous segmentation is kept.") : readyStatus());
    });
    connect(m_job, &BackgroundJobBase::failed, this, [this](const QString& message) {
        onRunEnded(m_runAnimation == m_animation ? tr("Segmentation failed: %1").arg(message) : readyStatus());
    });
    connect(m_stream, &SegmentStream::stepped, this, &SegmentationPanel::onStreamStep);
    connect(m_stream, &SegmentStream::finished, this, &SegmentationPanel::onStreamFinished);
    connect(m_stream, &SegmentStream::stopped, this, [this] {
        m_streamShown.reset();
        onRunEnded(tr("Stream stopped; the previous segmentation is kept."));
    });
    connect(m_stream, &SegmentStream::failed, this, [this](const QString& message) {
        m_streamShown.reset();
        onRunEnded(tr("Stream failed: %1").arg(message));
    });
}

void SegmentationPanel::setAnimation(std::shared_ptr<const LoadedAnimation> animation)
{
    m_stream->stop();
    m_job->cancel(); // its result, should it still arrive, counts as canceled
    m_animation = std::move(animation);
    m_result.reset();
    m_cleaned.reset();
    m_streamShown.reset();
    m_currentPose = 0;
    m_times->clear();
    refreshDisplay();
    updateControls();
    setStatus(readyStatus());
}

QString SegmentationPanel::readyStatus() const
{
    return m_animation
               ? tr("%1 poses. Press %2 to segment them.").arg(m_animation->animation->poseCount()).arg(runLabel())
               : tr("Open an animation (File ▸ Open Animation…) to segment it.");
}

QString SegmentationPanel::runLabel() const
{
    return m_choices.mode == SegmentationMode::RealTime ? tr("Stream poses") : tr("Run");
}

void SegmentationPanel::setCurrentPose(int pose)
{
    m_currentPose = pose;
    m_stream->poseReached(pose);
    if (m_choices.mode == SegmentationMode::Variable && m_result)
        refreshDisplay();
}

void SegmentationPanel::setChoices(const SegmentationChoices& choices)
{
    m_choices = choices;
    m_form->setChoices(choices);
    {
        const QSignalBlocker sliderBlocker(m_hSlider);
        const QSignalBlocker colorBlocker(m_colorBySegment);
        m_hSlider->setValue(int(std::lround(choices.h * kHSteps)));
        m_colorBySegment->setChecked(choices.colorBySegment);
    }
    m_hLabel->setText(QStringLiteral("h = %1").arg(m_choices.h, 0, 'f', 3));
    m_stream->setH(m_choices.h);
    updateControls();
    if (m_result)
        applyH();
    else
        refreshDisplay();
}

void SegmentationPanel::onFormChanged()
{
    const SegmentationMode mode = m_choices.mode;
    m_choices = m_form->applyTo(m_choices);
    if (mode != m_choices.mode && m_choices.mode != SegmentationMode::RealTime)
        m_stream->stop();
    if (m_result && !isRunning())
        setStatus(settingsMatchResult() ? tr("Showing the last run.")
                                        : tr("Settings changed: %1 to apply them.").arg(runLabel()));
    else if (!m_result && !isRunning() && mode != m_choices.mode)
        setStatus(readyStatus()); // it names the button, whose label follows the mode
    updateControls();
    refreshDisplay();
    emit choicesChanged();
}

void SegmentationPanel::onHSliderMoved(int value)
{
    m_choices.h = double(value) / kHSteps;
    m_hLabel->setText(QStringLiteral("h = %1").arg(m_choices.h, 0, 'f', 3));
    m_stream->setH(m_choices.h);
    // At once: re-cleaning and recoloring take a few ms even on large meshes (see
    // lastCleaningMs()); the viewport's update() merges a burst into one frame.
    applyH();
    emit choicesChanged();
}

// Re-cleans the result for the slider's h and recolors from the colors shown before.
void SegmentationPanel::applyH()
{
    if (!m_result) {
        updateCountLabel();
        return;
    }
    const AnimationSegmenter& segmenter = *m_result->segmenter;
    QElapsedTimer timer;
    timer.start();
    VertexLabeling labeling = segmenter.segment(m_choices.h);
    m_cleaningMs = elapsedMs(timer);
    timer.restart();
    m_cleaned.show(segmenter.graph(), segmenter.vertexAreas(), std::move(labeling));
    refreshDisplay();
    m_coloringMs = elapsedMs(timer);
    showTimes(segmenter.times(), m_cleaningMs);
}

void SegmentationPanel::onColorToggled(bool on)
{
    m_choices.colorBySegment = on;
    refreshDisplay();
    emit choicesChanged();
}

void SegmentationPanel::run()
{
    if (!m_animation || isRunning())
        return;
    if (m_choices.mode == SegmentationMode::RealTime)
        startStream();
    else
        startRun();
    updateControls();
}

void SegmentationPanel::startRun()
{
    m_pendingSettings = m_choices.segmenterSettings();
    m_runAnimation = m_animation;
    SegmentationRunOptions options;
    options.settings = m_pendingSettings;
    m_job->start([animation = m_animation->animation, options](const TaskControl& control) {
        return runSegmentation(*animation, options, control);
    });
    m_presenter->showStarted(tr("Segmenting…"));
}

void SegmentationPanel::startStream()
{
    m_pendingSettings = m_choices.segmenterSettings();
    try {
        m_stream->start(m_animation->animation, m_pendingSettings, m_choices.h);
    } catch (const std::exception& e) {
        setStatus(QString::fromStdString(e.what()));
        return;
    }
    m_streamShown.reset();
    m_progress->setRange(0, int(m_animation->animation->poseCount()));
    m_progress->setValue(0);
    m_progress->setFormat(tr("%v / %m poses"));
    m_progress->setVisible(true);
    setStatus(tr("Streaming poses as the timeline plays…"));
    emit streamStarted();
}

void SegmentationPanel::cancel()
{
    if (m_stream->isRunning()) {
        m_stream->stop();
        return;
    }
    if (m_presenter->cancel())
        updateControls();
}

void SegmentationPanel::onRunSucceeded()
{
    std::shared_ptr<const SegmentationResult> result = m_job->takeResult();
    // Every pose but the rest pose is partitioned: name the animation's pose count, with
    // the partitions beside it (it read "47 poses" for a 48-pose animation).
    const std::size_t poses = result->segmenter->animation().poseCount();
    const std::size_t partitions = result->segmenter->partitionedPoses().size();
    adoptResult(std::move(result), m_pendingSettings);
    onRunEnded(tr("Done: %1 poses segmented (%2 pose partitions joined).").arg(poses).arg(partitions));
}

void SegmentationPanel::onRunEnded(const QString& status)
{
    m_progress->setVisible(false);
    m_progress->resetFormat();
    setStatus(status);
    updateControls();
    refreshDisplay();
}

void SegmentationPanel::onStreamStep(const StreamStep& step)
{
    m_streamShown.showColored(step.labeling, step.colors);
    m_progress->setValue(step.processed);
    setStatus(tr("Streamed %1 of %2 poses.").arg(step.processed).arg(m_stream->poseCount()));
    showTimes(step.times, std::nullopt);
    m_times->setText(m_times->text() + tr(" · last pose %1").arg(milliseconds(step.stepMs)));
    refreshDisplay();
}

void SegmentationPanel::onStreamFinished(std::shared_ptr<const SegmentationResult> result)
{
    m_cleaned = m_streamShown; // the colors carry over to h changes
    m_streamShown.reset();
    const int poses = int(result->segmenter->animation().poseCount());
    adoptResult(std::move(result), m_pendingSettings);
    onRunEnded(tr("Streamed all %1 poses.").arg(poses));
}

void SegmentationPanel::adoptResult(std::shared_ptr<const SegmentationResult> result, const SegmenterSettings& settings)
{
    m_result = std::move(result);
    m_resultSettings = settings;
    applyH();
    emit resultChanged();
}

SegmentationPanel::Shown SegmentationPanel::shown() const
{
    if (m_choices.mode == SegmentationMode::Variable) {
        if (!m_result || m_result->variable.empty())
            return {};
        const std::size_t index = m_result->variableIndexAt(std::size_t(std::max(m_currentPose, 0)));
        return {&m_result->variable[index], &m_result->variableColors[index]};
    }
    if (m_choices.mode == SegmentationMode::RealTime && m_stream->isRunning())
        return m_streamShown.empty() ? Shown{} : Shown{&m_streamShown.labeling(), &m_streamShown.colors()};
    if (m_cleaned.empty())
        return {};
    return {&m_cleaned.labeling(), &m_cleaned.colors()};
}

const VertexLabeling* SegmentationPanel::shownLabeling() const
{
    return shown().labeling;
}

const std::vector<WheelColor>* SegmentationPanel::shownColors() const
{
    return shown().colors;
}

void SegmentationPanel::refreshDisplay()
{
    const Shown now = shown();
    if (m_choices.colorBySegment && now.labeling)
        m_displayColors = vertexRgba8(*now.labeling, *now.colors);
    else
        m_displayColors.clear();
    updateCountLabel();
    emit displayColorsChanged();
}

void SegmentationPanel::updateCountLabel()
{
    const Shown now = shown();
    if (!now.labeling) {
        m_count->setText(tr("No segmentation yet."));
        return;
    }
    const std::uint32_t count = now.labeling->count;
    if (m_choices.mode == SegmentationMode::Variable)
        m_count->setText(tr("Segments: %1 at pose %2 (joined with the next pose)").arg(count).arg(m_currentPose));
    else if (m_choices.mode == SegmentationMode::RealTime && m_stream->isRunning())
        m_count->setText(tr("Segments: %1 after %2 poses").arg(count).arg(m_stream->processedPoses()));
    else
        m_count->setText(
            tr("Segments: %1 (over-segmentation %2)").arg(count).arg(m_result->segmenter->overSegmentation().count));
}

void SegmentationPanel::showTimes(const SegmentationTimes& times, std::optional<double> cleaningMs)
{
    QString text = tr("features %1 · partitions %2 · over-segmentation %3")
                       .arg(milliseconds(times.featuresMs), milliseconds(times.partitionsMs),
                            milliseconds(times.overSegmentationMs));
    if (cleaningMs)
        text += tr(" · cleaning %1").arg(milliseconds(*cleaningMs));
    m_times->setText(text);
}

void SegmentationPanel::updateControls()
{
    const bool available = m_animation != nullptr;
    const bool running = isRunning();
    m_form->setEnabled(available && !running);
    m_run->setText(runLabel());
    m_presenter->updateRow(available, m_stream->isRunning());
    m_hSlider->setEnabled(available && m_choices.mode != SegmentationMode::Variable);
    m_colorBySegment->setEnabled(available);
    m_export->setEnabled(m_result != nullptr);
}

void SegmentationPanel::setStatus(const QString& text)
{
    m_status->setText(text);
}

bool SegmentationPanel::isRunning() const
{
    return m_job->isRunning() || m_stream->isRunning();
}

bool SegmentationPanel::settingsMatchResult() const
{
    const SegmenterSettings wanted = m_choices.segmenterSettings();
    return wanted.feature.kind == m_resultSettings.feature.kind &&
           wanted.feature.reference == m_resultSettings.feature.reference &&
           wanted.partition.method == m_resultSettings.partition.method &&
           wanted.partition.clusters == m_resultSettings.partition.clusters;
}

bool SegmentationPanel::exportSegmentation(const QString& path, QString* error)
{
    QString reason;
    const std::optional<SegmentationFileFormat> format = segmentationFileFormat(path.toStdString());
    if (!m_result || m_cleaned.empty())
        reason = tr("There is no segmentation yet: press Run first.");
    else if (!format)
        reason = tr("“%1” is not a .json, .csv or .gltf file.").arg(path);
    else {
        try {
            const AnimationSegmenter& segmenter = *m_result->segmenter;
            SegmentationRecord record =
                makeSegmentationRecord(segmenter, m_animation->restScene->source, m_choices.h, m_cleaned.labeling(),
                                       m_cleaned.colors(), m_choices.mode == SegmentationMode::Variable);
            record.times.load = m_animation->loadMs;
            record.times.cleaning = m_cleaningMs;
            writeSegmentationFile(path.toStdString(), *format, record, segmenter.animation());
        } catch (const std::exception& e) {
            reason = QString::fromStdString(e.what());
        }
    }
    if (error)
        *error = reason;
    return reason.isEmpty();
}

} // namespace trimlab::ui
