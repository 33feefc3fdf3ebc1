// The typed background job (ui/common/background_job.h) on real core work: loading a
// mesh animation from tests/data returns it typed, with the loader's progress; a broken
// file fails with the loader's reason; a held load canceled midway ends canceled with no
// result; work that returns after cancel() still counts as canceled; a second start()
// while running is refused; a destroyed job waits for its work; an abandoned job tells
// its receiver nothing more and deletes itself.
#include "held_background_job.h"
#include "test_paths.h"

#include "ui/common/background_job.h"

#include "core/animation/animation_loader.h"
#include "core/mesh/mesh_io.h"

#include <QPointer>
#include <QSignalSpy>
#include <QtTest>

#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

constexpr int kWaitMs = 30000;

std::string animationPath(const char* name)
{
    return test::testDataPath(std::string("animations/") + name).string();
}

/// Starts `job` on `work` and waits for finished(); false on a timeout.
template <class T>
bool runAndWait(BackgroundJob<T>& job, typename BackgroundJob<T>::Work work)
{
    QSignalSpy finished(&job, &BackgroundJobBase::finished);
    job.start(std::move(work));
    return QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs);
}

} // namespace

class TestBackgroundJob : public QObject {
    Q_OBJECT
private slots:
    void returnsTheTypedResultWithProgress();
    void failureCarriesTheCoreReason();
    void cancelMidwayLeavesNoResult();
    void workReturningAfterCancelCountsAsCanceled();
    void voidJobSucceeds();
    void secondStartWhileRunningIsRefused();
    void destroyingARunningJobWaitsForItsWork();
    void abandonedJobGoesQuietlyAndDeletesItself();
};

void TestBackgroundJob::returnsTheTypedResultWithProgress()
{
    BackgroundJob<std::shared_ptr<const MeshAnimation>> job;
    QSignalSpy progressed(&job, &BackgroundJobBase::progressed);
    QSignalSpy succeeded(&job, &BackgroundJobBase::succeeded);
    QVERIFY(!job.hasResult());
    QVERIFY(runAndWait(job, [path = animationPath("folding_box")](const TaskControl& control) {
        return std::make_shared<const MeshAnimation>(loadAnimation(path, {}, control));
    }));
    QCOMPARE(succeeded.size(), 1);
    QVERIFY(!job.isRunning());
    QVERIFY(job.hasResult());
    const std::shared_ptr<const MeshAnimation> loaded = job.result();
    QCOMPARE(loaded->poseCount(), std::size_t(3));
    QCOMPARE(loaded->vertexCount(), std::size_t(20));
    // The loader's reports, queued to this thread: stage "load", counts within the total,
    // the last one complete.
    QTRY_VERIFY(!progressed.isEmpty());
    for (const QList<QVariant>& report : progressed) {
        QCOMPARE(report.at(0).toString(), QStringLiteral("load"));
        QVERIFY(report.at(1).toLongLong() <= report.at(2).toLongLong());
    }
    QCOMPARE(progressed.last().at(1).toLongLong(), progressed.last().at(2).toLongLong());
    QCOMPARE(job.takeResult(), loaded);
    QVERIFY(!job.hasResult());
    QVERIFY_THROWS_EXCEPTION(std::logic_error, (void)job.result());
}

void TestBackgroundJob::failureCarriesTheCoreReason()
{
    BackgroundJob<std::shared_ptr<const MeshAnimation>> job;
    QSignalSpy failed(&job, &BackgroundJobBase::failed);
    QSignalSpy succeeded(&job, &BackgroundJobBase::succeeded);
    QVERIFY(runAndWait(job, [path = animationPath("broken_pose")](const TaskControl& control) {
        return std::make_shared<const MeshAnimation>(loadAnimation(path, {}, control));
    }));
    QCOMPARE(failed.size(), 1);
    QCOMPARE(succeeded.size(), 0);
    const QString message = failed.first().at(0).toString();
    QVERIFY2(message.contains(QStringLiteral("mesh_0001.obj:9")), qPrintable(message));
    QVERIFY(!job.hasResult());
}

void TestBackgroundJob::cancelMidwayLeavesNoResult()
{
    BackgroundJob<std::shared_ptr<const MeshAnimation>> job;
    QSignalSpy canceled(&job, &BackgroundJobBase::canceled);
    QSignalSpy succeeded(&job, &BackgroundJobBase::succeeded);
    QSignalSpy finished(&job, &BackgroundJobBase::finished);
    test::HeldBackgroundJob held(&job);
    job.start([path = animationPath("folding_box")](const TaskControl& control) {
        return std::make_shared<const MeshAnimation>(loadAnimation(path, {}, control));
    });
    QVERIFY(held.waitUntilHeld(kWaitMs));
    QVERIFY(job.isRunning());
    QVERIFY(!job.cancelRequested());
    job.cancel();
    QVERIFY(job.cancelRequested());
    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QCOMPARE(canceled.size(), 1);
    QCOMPARE(succeeded.size(), 0);
    QVERIFY(!job.hasResult());
    QVERIFY(!job.cancelRequested());

    // The same job runs again to the end afterwards.
    QVERIFY(runAndWait(job, [path = animationPath("folding_box")](const TaskControl& control) {
        return std::make_shared<const MeshAnimation>(loadAnimation(path, {}, control));
    }));
    QCOMPARE(succeeded.size(), 1);
    QCOMPARE(job.result()->poseCount(), std::size_t(3));
}

// The work reports once (held there), ignores the stop request and returns a value.
void TestBackgroundJob::workReturningAfterCancelCountsAsCanceled()
{
    BackgroundJob<int> job;
    QSignalSpy canceled(&job, &BackgroundJobBase::canceled);
    QSignalSpy finished(&job, &BackgroundJobBase::finished);
    test::HeldBackgroundJob held(&job);
    job.start([](const TaskControl& control) {
        control.report("step", 0, 1);
        return 42;
    });
    QVERIFY(held.waitUntilHeld(kWaitMs));
    job.cancel();
    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QCOMPARE(canceled.size(), 1);
    QVERIFY(!job.hasResult());
}

void TestBackgroundJob::voidJobSucceeds()
{
    BackgroundJob<void> job;
    QSignalSpy succeeded(&job, &BackgroundJobBase::succeeded);
    std::size_t triangles = 0; // written by the work, read after finished()
    QVERIFY(runAndWait(job, [&triangles](const TaskControl&) {
        triangles = loadMesh(test::testDataPath("meshes/cube.obj")).triangleCount();
    }));
    QCOMPARE(succeeded.size(), 1);
    QVERIFY(job.hasResult());
    QCOMPARE(triangles, std::size_t(12));
}

void TestBackgroundJob::secondStartWhileRunningIsRefused()
{
    BackgroundJob<int> job;
    QSignalSpy finished(&job, &BackgroundJobBase::finished);
    test::HeldBackgroundJob held(&job);
    job.start([](const TaskControl& control) {
        control.report("step", 0, 1);
        return 1;
    });
    QVERIFY(held.waitUntilHeld(kWaitMs));
    QVERIFY_THROWS_EXCEPTION(std::logic_error, job.start([](const TaskControl&) { return 2; }));
    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QCOMPARE(job.result(), 1);
}

void TestBackgroundJob::destroyingARunningJobWaitsForItsWork()
{
    auto returned = std::make_shared<std::atomic<bool>>(false);
    auto started = std::make_shared<std::atomic<bool>>(false);
    {
        BackgroundJob<int> job;
        job.start([returned, started](const TaskControl& control) {
            started->store(true);
            while (!control.stop.stop_requested())
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            returned->store(true);
            control.throwIfCancelled();
            return 0;
        });
        QVERIFY(QTest::qWaitFor([&] { return started->load(); }, kWaitMs));
        QVERIFY(!returned->load());
    } // the destructor asks the work to stop and waits for it
    QVERIFY(returned->load());
}

void TestBackgroundJob::abandonedJobGoesQuietlyAndDeletesItself()
{
    QObject owner;
    QPointer<BackgroundJob<int>> job = new BackgroundJob<int>(&owner);
    int heard = 0;
    connect(job, &BackgroundJobBase::finished, &owner, [&heard] { ++heard; });
    auto proceed = std::make_shared<std::atomic<bool>>(false);
    job->start([proceed](const TaskControl& control) {
        while (!proceed->load())
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        control.throwIfCancelled();
        return 0;
    });
    job->abandon(&owner);
    QVERIFY(job); // still running: alive until its work returns
    QVERIFY(job->cancelRequested());
    proceed->store(true);
    QVERIFY(QTest::qWaitFor([&] { return job.isNull(); }, kWaitMs));
    QCOMPARE(heard, 0);

    QPointer<BackgroundJob<int>> idle = new BackgroundJob<int>(&owner);
    idle->abandon(&owner);
    QVERIFY(QTest::qWaitFor([&] { return idle.isNull(); }, kWaitMs));
}

QTEST_GUILESS_MAIN(TestBackgroundJob)
#include "tst_background_job.moc"
