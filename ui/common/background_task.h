#pragma once
/// \file
/// One long core operation off the UI thread (QtConcurrent on the global thread pool),
/// driven through the core's TaskControl (util/task_control.h): progress reports
/// become progressed() signals, cancel() requests the job's std::stop_token, and exactly
/// one of succeeded(), failed() or canceled() follows each start(), then finished().
///
/// The job hands its result back through whatever it captured (e.g. a shared_ptr the
/// caller reads in succeeded()). A task can be started again once it has finished.
/// Destroying a running task requests stop and waits for the job, so a job never
/// outlives the object it reports through.

#include "core/util/task_control.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <stop_token>

namespace trimlab::ui {

class BackgroundTask : public QObject {
    Q_OBJECT
public:
    using Job = std::function<void(const TaskControl&)>;

    explicit BackgroundTask(QObject* parent = nullptr);
    ~BackgroundTask() override;

    /// Starts `job` on a worker thread. Throws std::logic_error while a job is running.
    void start(Job job);
    /// Requests the running job to stop (no-op when idle). canceled() follows once the
    /// job has returned; a job that returns normally after the request counts as
    /// canceled too, so its result is never used.
    void cancel();

    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] bool cancelRequested() const { return m_running && m_stop.stop_requested(); }

signals:
    /// `done` of `total` items of `stage` ("load", "features", "partitions", …) are
    /// finished. Emitted on the worker thread: connect with the default (auto)
    /// connection and receivers on the UI thread get it queued.
    void progressed(const QString& stage, qint64 done, qint64 total);
    void succeeded();
    /// `message` is the exception's text (MeshLoadError's names the file).
    void failed(const QString& message);
    void canceled();
    /// After any of the three above.
    void finished();

private:
    /// How a job ended.
    struct Outcome {
        enum class Kind { Succeeded, Failed, Canceled } kind = Kind::Succeeded;
        QString message;
    };

    [[nodiscard]] Outcome runJob(const Job& job, std::stop_token stop);
    void report(const Outcome& outcome);

    QFutureWatcher<Outcome> m_watcher;
    std::stop_source m_stop;
    bool m_running = false;
};

} // namespace trimlab::ui
