#include "ui/animation/animation_opener.h"

#include "ui/common/background_job.h"
#include "ui/common/task_progress_dialog.h"

#include <QFileInfo>
#include <QProgressDialog>

#include <algorithm>
#include <utility>

namespace trimlab::ui {

namespace {

QString shortName(const QString& source)
{
    const QFileInfo info(source);
    const QString name = info.fileName().isEmpty() ? QFileInfo(info.path()).fileName() : info.fileName();
    return name.isEmpty() ? source : name;
}

} // namespace

AnimationOpener::AnimationOpener(QWidget* dialogParent) : QObject(dialogParent), m_dialogParent(dialogParent)
{
}

AnimationOpener::~AnimationOpener()
{
    closeProgress();
}

void AnimationOpener::open(const QString& source)
{
    abandonTask();
    m_source = source;
    auto* job = new BackgroundJob<std::shared_ptr<const LoadedAnimation>>(this);
    m_task = job;
    connect(job, &BackgroundJobBase::progressed, this, &AnimationOpener::updateProgress);
    connect(job, &BackgroundJobBase::succeeded, this, [this, job] { finishLoad(job->takeResult()); });
    connect(job, &BackgroundJobBase::failed, this, &AnimationOpener::failLoad);
    connect(job, &BackgroundJobBase::canceled, this, &AnimationOpener::cancel);
    job->start([path = source.toStdString()](const TaskControl& control) {
        return std::make_shared<const LoadedAnimation>(loadAnimationForDisplay(path, control));
    });
    showProgress(source);
}

QProgressDialog* AnimationOpener::progressDialog() const
{
    return m_progress.data();
}

void AnimationOpener::cancel()
{
    if (!m_task)
        return;
    abandonTask();
    emit canceled(m_source);
}

// Stops the pending job and lets it delete itself once its worker has returned; its
// signals no longer reach this object.
void AnimationOpener::abandonTask()
{
    closeProgress();
    if (m_task)
        std::exchange(m_task, nullptr)->abandon(this);
}

void AnimationOpener::finishLoad(std::shared_ptr<const LoadedAnimation> animation)
{
    abandonTask();
    emit loaded(std::move(animation));
}

void AnimationOpener::failLoad(const QString& message)
{
    abandonTask();
    emit failed(m_source, message);
}

void AnimationOpener::showProgress(const QString& source)
{
    // Busy (0..0) until the loader says how many files there are. The dialog shows itself
    // once the minimum duration has passed since setValue(minimum). Not modal: a modal
    // QProgressDialog runs the event loop inside setValue(), and the load's own end could
    // then arrive in the middle of a progress update.
    m_progress = new QProgressDialog(tr("Loading %1…").arg(shortName(source)), tr("Cancel"), 0, 0, m_dialogParent);
    m_progress->setObjectName(QStringLiteral("animationProgressDialog"));
    m_progress->setWindowTitle(tr("Opening Animation"));
    m_progress->setWindowModality(Qt::NonModal);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setMinimumDuration(m_progressDelayMs);
    connect(m_progress, &QProgressDialog::canceled, this, &AnimationOpener::cancel);
    m_progress->setValue(0);
}

void AnimationOpener::updateProgress(const QString& stage, qint64 done, qint64 total)
{
    // Progress arrives queued from the worker: drop what an abandoned task sent.
    if (!m_progress || total <= 0 || sender() != m_task)
        return;
    Q_UNUSED(stage);
    m_progress->setLabelText(tr("Loading %1… (%2 of %3)").arg(shortName(m_source)).arg(done).arg(total));
    m_progress->setMaximum(int(total));
    m_progress->setValue(int(std::min(done, total)));
}

void AnimationOpener::closeProgress()
{
    closeProgressDialog(m_progress);
}

} // namespace trimlab::ui
