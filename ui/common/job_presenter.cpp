#include "ui/common/job_presenter.h"

#include "ui/common/background_job.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <algorithm>

namespace trimlab::ui {

namespace {

/// The bar's range is an int; counts beyond it are scaled by the bar's percentage anyway.
constexpr qint64 kLargestRange = qint64(1) << 30;

} // namespace

JobPresenter::JobPresenter(BackgroundJobBase* job, const Widgets& widgets, ProgressText text, QObject* parent)
    : QObject(parent), m_job(job), m_widgets(widgets), m_text(text)
{
    m_widgets.progress->setVisible(false);
    connect(m_job, &BackgroundJobBase::progressed, this, &JobPresenter::showProgress);
    connect(m_job, &BackgroundJobBase::succeeded, this, &JobPresenter::hideProgress);
    connect(m_job, &BackgroundJobBase::canceled, this, &JobPresenter::hideProgress);
    connect(m_job, &BackgroundJobBase::failed, this, &JobPresenter::hideProgress);
}

void JobPresenter::showStarted(const QString& status)
{
    m_widgets.progress->setRange(0, 0);
    m_widgets.progress->setVisible(true);
    setStatus(status);
}

bool JobPresenter::cancel()
{
    if (!m_job->isRunning())
        return false;
    m_job->cancel();
    setStatus(tr("Canceling…"));
    m_widgets.cancel->setEnabled(false);
    return true;
}

void JobPresenter::updateRow(bool canRun, bool otherWork) const
{
    const bool running = m_job->isRunning() || otherWork;
    m_widgets.run->setEnabled(canRun && !running);
    m_widgets.cancel->setEnabled(otherWork || (m_job->isRunning() && !m_job->cancelRequested()));
}

void JobPresenter::setStatus(const QString& text) const
{
    m_widgets.status->setText(text);
}

void JobPresenter::showProgress(const QString& stage, qint64 done, qint64 total)
{
    if (!m_job->isRunning() || total <= 0)
        return; // a late report of a job that has ended
    if (total == 1) {
        // One step: "0 / 1" would read like a count of nothing; the busy bar and the
        // stage's name say what runs.
        m_widgets.progress->setRange(0, 0);
        m_widgets.progress->setFormat(tr("%1…").arg(stage));
        return;
    }
    const qint64 range = std::min(total, kLargestRange);
    const qint64 value = std::min(done, total);
    m_widgets.progress->setRange(0, int(range));
    m_widgets.progress->setValue(range == total ? int(value) : int(double(value) / double(total) * double(range)));
    m_widgets.progress->setFormat(m_text == ProgressText::Percent ? tr("%1: %p%").arg(stage)
                                                                  : tr("%1: %v / %m").arg(stage));
}

void JobPresenter::hideProgress()
{
    m_widgets.progress->setVisible(false);
    m_widgets.progress->resetFormat();
}

} // namespace trimlab::ui
