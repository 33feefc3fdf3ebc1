#include "ui/common/background_job.h"

#include <new>

namespace trimlab::ui {

BackgroundJobBase::BackgroundJobBase(QObject* parent) : QObject(parent)
{
}

void BackgroundJobBase::cancel()
{
    if (m_running)
        m_stop.request_stop();
}

void BackgroundJobBase::abandon(QObject* receiver)
{
    disconnect(receiver);
    if (!m_running) {
        deleteLater();
        return;
    }
    connect(this, &BackgroundJobBase::finished, this, &QObject::deleteLater);
    cancel();
}

TaskControl BackgroundJobBase::beginRun()
{
    if (m_running)
        throw std::logic_error("BackgroundJob::start while a run is under way");
    m_stop = std::stop_source();
    m_running = true;
    TaskControl control;
    control.stop = m_stop.get_token();
    control.progress = [this](const TaskProgress& progress) {
        emit progressed(QString::fromUtf8(progress.stage.data(), qsizetype(progress.stage.size())),
                        qint64(progress.done), qint64(progress.total));
    };
    return control;
}

void BackgroundJobBase::endRun(const JobEnding& ending)
{
    m_running = false;
    switch (ending.kind) {
    case JobEnding::Kind::Succeeded:
        emit succeeded();
        break;
    case JobEnding::Kind::Failed:
        emit failed(ending.message);
        break;
    case JobEnding::Kind::Canceled:
        emit canceled();
        break;
    }
    emit finished();
}

JobEnding BackgroundJobBase::runCatching(const std::function<void()>& work, const std::stop_token& stop)
{
    try {
        work();
    } catch (const OperationCancelled&) {
        return {JobEnding::Kind::Canceled, {}};
    } catch (const std::bad_alloc&) {
        return {JobEnding::Kind::Failed, tr("There is not enough memory for this.")};
    } catch (const std::exception& e) {
        return {JobEnding::Kind::Failed, QString::fromStdString(e.what())};
    }
    if (stop.stop_requested())
        return {JobEnding::Kind::Canceled, {}};
    return {JobEnding::Kind::Succeeded, {}};
}

} // namespace trimlab::ui
