#pragma once
/// \file
/// Holding a panel's background job while it runs, so that a widget test can act at a
/// known point of the run (cancel it, edit other controls) instead of racing the worker.

#include "ui/common/background_job.h"

#include <QObject>
#include <QSemaphore>

#include <atomic>

namespace trimlab::test {

/// Blocks `task`'s worker thread inside the job's first progress report after
/// construction, until release() or destruction; later reports pass. Start the task
/// after constructing this, then waitUntilHeld(). The destructor lets the worker go and
/// disconnects, so a test that fails early does not leave the worker blocked.
class HeldBackgroundJob {
public:
    explicit HeldBackgroundJob(ui::BackgroundJobBase* task)
    {
        m_connection = QObject::connect(
            task, &ui::BackgroundJobBase::progressed, task,
            [this](const QString&, qint64, qint64) {
                if (!m_first.exchange(false))
                    return;
                m_held.release();
                m_resume.acquire(); // the worker waits here until the test lets it go
            },
            Qt::DirectConnection); // run on the worker thread: that is the thread to hold
    }
    ~HeldBackgroundJob()
    {
        m_resume.release();
        stop();
    }
    HeldBackgroundJob(const HeldBackgroundJob&) = delete;
    HeldBackgroundJob& operator=(const HeldBackgroundJob&) = delete;

    /// True when the worker reached its first progress report within `timeoutMs`.
    [[nodiscard]] bool waitUntilHeld(int timeoutMs) { return m_held.tryAcquire(1, timeoutMs); }
    /// Lets the held worker go on.
    void release() { m_resume.release(); }
    /// Stops watching the task (a later run is not held either way).
    void stop() { QObject::disconnect(m_connection); }

private:
    QSemaphore m_held;
    QSemaphore m_resume;
    std::atomic<bool> m_first{true};
    QMetaObject::Connection m_connection;
};

} // namespace trimlab::test
