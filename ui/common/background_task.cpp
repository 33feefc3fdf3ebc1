#include "ui/common/background_task.h"

#include <QtConcurrent/QtConcurrentRun>

#include <new>
#include <stdexcept>

namespace trimlab::ui {

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent)
{
    connect(&m_watcher, &QFutureWatcher<Outcome>::finished, this, [this] { report(m_watcher.result()); });
}

BackgroundTask::~BackgroundTask()
{
    if (!m_running)
        return;
    m_watcher.disconnect(this);
    m_stop.request_stop();
    m_watcher.waitForFinished();
}

void BackgroundTask::start(Job job)
{
    if (m_running)
        throw std::logic_error("BackgroundTask::start while a job is running");
    m_stop = std::stop_source();
    m_running = true;
    m_watcher.setFuture(QtConcurrent::run(
        [this, job = std::move(job), stop = m_stop.get_token()] { return runJob(job, stop); }));
}

void BackgroundTask::cancel()
{
    if (m_running)
        m_stop.request_stop();
}

// On the worker thread; never throws (exceptions must not cross QtConcurrent::run).
BackgroundTask::Outcome BackgroundTask::runJob(const Job& job, std::stop_token stop)
{
    TaskControl control;
    control.stop = stop;
    control.progress = [this](const TaskProgress& progress) {
        emit progressed(QString::fromUtf8(progress.stage.data(), qsizetype(progress.stage.size())),
                        qint64(progress.done), qint64(progress.total));
    };
    try {
        job(control);
    } catch (const OperationCancelled&) {
        return {Outcome::Kind::Canceled, {}};
    } catch (const std::bad_alloc&) {
        return {Outcome::Kind::Failed, tr("There is not enough memory for this.")};
    } catch (const std::exception& e) {
        return {Outcome::Kind::Failed, QString::fromStdString(e.what())};
    }
    if (stop.stop_requested())
        return {Outcome::Kind::Canceled, {}};
    return {Outcome::Kind::Succeeded, {}};
}

void BackgroundTask::report(const Outcome& outcome)
{
    m_running = false;
    switch (outcome.kind) {
    case Outcome::Kind::Succeeded: emit succeeded(); break;
    case Outcome::Kind::Failed: emit failed(outcome.message); break;
    case Outcome::Kind::Canceled: emit canceled(); break;
    }
    emit finished();
}

} // namespace trimlab::ui
