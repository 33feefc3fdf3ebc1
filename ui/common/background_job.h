#pragma once
/// \file
/// One long core operation off the UI thread, typed by what it returns.
/// BackgroundJob<T> runs a `T(const TaskControl&)` on the global thread pool
/// (QtConcurrent) and hands the T back on the UI thread; BackgroundJob<void> runs work
/// that returns nothing. Every job follows one protocol (BackgroundJobBase), so that a
/// panel, a dialog or a test handles any of them alike:
/// - the core's progress reports (util/task_control.h) become progressed() signals;
/// - cancel() requests the job's std::stop_token;
/// - exactly one of succeeded(), failed() or canceled() follows each start(), then
///   finished(); result() is the value from succeeded() on until the next start().
///
/// A job that returns normally after cancel() counts as canceled, so a result computed
/// for a request that was withdrawn is never used. Destroying a running job requests stop
/// and waits for the work, so work never outlives the object it reports through; a caller
/// that must not wait lets the job go with abandon().

#include "core/util/task_control.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QtConcurrent/QtConcurrentRun>

#include <functional>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <type_traits>
#include <utility>
#include <variant>

namespace trimlab::ui {

/// How one run of a job ended; `message` is the failure's text.
struct JobEnding {
    enum class Kind { Succeeded, Failed, Canceled } kind = Kind::Succeeded;
    QString message;
};

/// The signals and the cancel protocol every BackgroundJob shares.
class BackgroundJobBase : public QObject {
    Q_OBJECT
public:
    /// Requests the running work to stop (no-op when idle); canceled() follows once the
    /// work has returned.
    void cancel();
    [[nodiscard]] bool isRunning() const { return m_running; }
    [[nodiscard]] bool cancelRequested() const { return m_running && m_stop.stop_requested(); }
    /// Lets the job go: `receiver` hears nothing more from it, running work is canceled
    /// and the job deletes itself once the work has returned (at once when idle). For an
    /// owner that starts a new job instead of waiting for an old one.
    void abandon(QObject* receiver);

signals:
    /// `done` of `total` items of `stage` ("load", "features", "contraction", …) are
    /// finished. Emitted on the worker thread: connect with the default (auto)
    /// connection and receivers on the UI thread get it queued.
    void progressed(const QString& stage, qint64 done, qint64 total);
    void succeeded();
    /// `message` is the exception's text (MeshLoadError's names the file).
    void failed(const QString& message);
    void canceled();
    /// After any of the three above.
    void finished();

protected:
    explicit BackgroundJobBase(QObject* parent);

    /// Begins a run: the TaskControl whose progress becomes progressed() and whose stop
    /// token is this run's. Throws std::logic_error while a run is under way.
    [[nodiscard]] TaskControl beginRun();
    /// Ends the run as `ending` says (on the UI thread): the signals above.
    void endRun(const JobEnding& ending);
    /// Requests stop of the running work (the derived job then waits for it).
    void requestStop() { m_stop.request_stop(); }
    /// Runs `work` on the calling (worker) thread and says how it ended; never throws:
    /// exceptions must not cross QtConcurrent::run.
    [[nodiscard]] static JobEnding runCatching(const std::function<void()>& work, const std::stop_token& stop);

private:
    std::stop_source m_stop;
    bool m_running = false;
};

template <class T>
class BackgroundJob final : public BackgroundJobBase {
public:
    using Work = std::function<T(const TaskControl&)>;
    /// What result() holds: T, or nothing for BackgroundJob<void>.
    using Value = std::conditional_t<std::is_void_v<T>, std::monostate, T>;

    explicit BackgroundJob(QObject* parent = nullptr) : BackgroundJobBase(parent)
    {
        connect(&m_watcher, &QFutureWatcherBase::finished, this, [this] { onWorkReturned(); });
    }
    ~BackgroundJob() override
    {
        if (!isRunning())
            return;
        m_watcher.disconnect(this);
        requestStop();
        m_watcher.waitForFinished();
    }
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    /// Starts `work` on a worker thread; forgets the previous result. Throws
    /// std::logic_error while a run is under way.
    void start(Work work)
    {
        TaskControl control = beginRun();
        m_result.reset();
        m_watcher.setFuture(QtConcurrent::run([work = std::move(work), control = std::move(control)] {
            Returned returned;
            returned.ending = runCatching(
                [&] {
                    if constexpr (std::is_void_v<T>) {
                        work(control);
                        returned.value.emplace();
                    } else {
                        returned.value.emplace(work(control));
                    }
                },
                control.stop);
            return returned;
        }));
    }

    /// Whether the last run succeeded and its value is still here (not taken).
    [[nodiscard]] bool hasResult() const { return m_result.has_value(); }
    /// The value of the last run that succeeded, from succeeded() until the next start().
    /// Throws std::logic_error when there is none.
    [[nodiscard]] const Value& result() const
    {
        if (!m_result)
            throw std::logic_error("BackgroundJob::result without a successful run");
        return *m_result;
    }
    /// Moves the value out (result() throws afterwards).
    [[nodiscard]] Value takeResult()
    {
        if (!m_result)
            throw std::logic_error("BackgroundJob::takeResult without a successful run");
        Value value = std::move(*m_result);
        m_result.reset();
        return value;
    }

private:
    struct Returned {
        JobEnding ending;
        std::optional<Value> value;
    };

    void onWorkReturned()
    {
        Returned returned = m_watcher.future().takeResult();
        if (returned.ending.kind == JobEnding::Kind::Succeeded)
            m_result = std::move(returned.value);
        endRun(returned.ending);
    }

    QFutureWatcher<Returned> m_watcher;
    std::optional<Value> m_result;
};

} // namespace trimlab::ui
