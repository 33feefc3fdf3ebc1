// The job presenter (ui/common/job_presenter.h) alone and in the three panels that run one
// long job each — Skeleton, Skinning, Segmentation — built on their own, without the main
// window and without an OpenGL context, on real inputs: a generated closed capsule and an
// open one, the folding box and a one-pose bar from tests/data. For each panel: Run
// produces the core's result with the row, bar and status following the job; a run held
// at its first progress report and canceled leaves no result; a refused input shows the
// core's reason.
#include "held_background_job.h"
#include "named_child.h"
#include "plain_obj.h"
#include "skeleton_shapes.h"
#include "test_paths.h"
#include "widget_test_main.h"

#include "ui/animation/segmentation_choices.h"
#include "ui/animation/segmentation_panel.h"
#include "ui/common/background_job.h"
#include "ui/common/job_presenter.h"
#include "ui/common/loaded_animation.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/skinning/skinning_panel.h"
#include "ui/skinning/skinning_session.h"

#include "core/catalog/scene_source.h"

#include <QComboBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace trimlab;
using namespace trimlab::ui;
using trimlab::test::child;

namespace {

constexpr int kWaitMs = 60000;

std::shared_ptr<const LoadedAnimation> loadTestAnimation(const char* name)
{
    const std::string path = test::testDataPath(std::string("animations/") + name).string();
    return std::make_shared<const LoadedAnimation>(loadAnimationForDisplay(path, {}));
}

/// Clicks `run` and waits for the job's finished(); false on a timeout.
bool clickAndWait(BackgroundJobBase* job, QPushButton* run)
{
    QSignalSpy finished(job, &BackgroundJobBase::finished);
    QTest::mouseClick(run, Qt::LeftButton);
    return QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs);
}

/// The row, bar and status of a panel's job.
struct Row {
    QPushButton* run;
    QPushButton* cancel;
    QProgressBar* progress;
    QLabel* status;
};

/// Clicks Run with the job held at its first report, checks the running row, clicks
/// Cancel, checks the canceling row, lets the job go and checks the idle row. False
/// (with a warning) when the job never reports or never ends.
bool runHeldAndCancel(BackgroundJobBase* job, const Row& row)
{
    test::HeldBackgroundJob held(job);
    QTest::mouseClick(row.run, Qt::LeftButton);
    if (!held.waitUntilHeld(kWaitMs)) {
        qWarning("the job never reported progress");
        return false;
    }
    if (!job->isRunning() || row.run->isEnabled() || !row.cancel->isEnabled() || !row.progress->isVisible()) {
        qWarning("the row does not show a running job");
        return false;
    }
    QTest::mouseClick(row.cancel, Qt::LeftButton);
    if (row.cancel->isEnabled() || row.status->text() != JobPresenter::tr("Canceling…")) {
        qWarning("the row does not show the cancel request");
        return false;
    }
    QSignalSpy canceled(job, &BackgroundJobBase::canceled);
    held.release();
    if (!QTest::qWaitFor([&] { return !job->isRunning(); }, kWaitMs) || canceled.size() != 1) {
        qWarning("the job did not end canceled");
        return false;
    }
    return row.run->isEnabled() && !row.cancel->isEnabled() && !row.progress->isVisible();
}

} // namespace

class TestJobPresenter : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void presenterFollowsAJob();
    void aStageOfOneStepShowsItsNameOnABusyBar();
    void skeletonPanelRunsCancelsAndRefuses();
    void skinningPanelFitsAndCancels();
    void segmentationPanelRunsCancelsAndRefuses();
    void segmentationStatusNamesTheRunButton();

private:
    QTemporaryDir m_dir;
    QString m_capsule;
    QString m_openCapsule;
};

void TestJobPresenter::initTestCase()
{
    QVERIFY(m_dir.isValid());
    const TriangleMesh capsule = test::axisCapsule(0.5, 1.0, 6, 10, 16);
    m_capsule = m_dir.filePath(QStringLiteral("capsule.obj"));
    QVERIFY(test::writePlainObj(capsule, m_capsule));
    TriangleMesh open = capsule;
    open.triangles.resize(open.triangles.size() - 3); // a hole at one cap
    m_openCapsule = m_dir.filePath(QStringLiteral("open-capsule.obj"));
    QVERIFY(test::writePlainObj(open, m_openCapsule));
}

// The presenter on plain widgets and a real load: busy bar and status at the start, the
// loader's stage and count on the bar, the bar hidden at the end, late reports dropped.
void TestJobPresenter::presenterFollowsAJob()
{
    QWidget host;
    auto* run = new QPushButton(&host);
    auto* cancel = new QPushButton(&host);
    auto* progress = new QProgressBar(&host);
    auto* status = new QLabel(&host);
    host.show();
    BackgroundJob<std::shared_ptr<const LoadedAnimation>> job;
    JobPresenter presenter(&job, {run, cancel, progress, status}, JobPresenter::ProgressText::Count);
    QVERIFY(!progress->isVisible());
    presenter.updateRow(false);
    QVERIFY(!run->isEnabled());
    presenter.updateRow(true);
    QVERIFY(run->isEnabled() && !cancel->isEnabled());
    QVERIFY(!presenter.cancel()); // idle: nothing to cancel

    test::HeldBackgroundJob held(&job);
    const std::string path = test::testDataPath("animations/folding_box").string();
    job.start([path](const TaskControl& control) {
        return std::make_shared<const LoadedAnimation>(loadAnimationForDisplay(path, control));
    });
    presenter.showStarted(QStringLiteral("Loading…"));
    presenter.updateRow(true);
    QVERIFY(progress->isVisible());
    QCOMPARE(progress->maximum(), 0); // busy until the first report arrives
    QCOMPARE(status->text(), QStringLiteral("Loading…"));
    QVERIFY(!run->isEnabled() && cancel->isEnabled());
    QVERIFY(held.waitUntilHeld(kWaitMs));
    QTRY_VERIFY(progress->maximum() > 0); // the held report, queued to this thread
    QVERIFY2(progress->format().startsWith(QStringLiteral("load: ")), qPrintable(progress->format()));
    QVERIFY(progress->value() <= progress->maximum());
    QSignalSpy finished(&job, &BackgroundJobBase::finished);
    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
    QVERIFY(!progress->isVisible());
    presenter.updateRow(true);
    QVERIFY(run->isEnabled() && !cancel->isEnabled());
    QCOMPARE(job.result()->animation->poseCount(), std::size_t(3));
    // A report of the finished job, arriving late, changes nothing.
    emit job.progressed(QStringLiteral("late"), 1, 2);
    QVERIFY(!progress->isVisible());
    QVERIFY(!progress->format().startsWith(QStringLiteral("late")));
}

// A stage reported as step 0 of 1 (the per-pose segments of a segmentation run) reads
// as its name on a busy bar, not as "0 / 1".
void TestJobPresenter::aStageOfOneStepShowsItsNameOnABusyBar()
{
    QWidget host;
    BackgroundJob<std::shared_ptr<const LoadedAnimation>> job;
    auto* progress = new QProgressBar(&host);
    JobPresenter presenter(&job, {new QPushButton(&host), new QPushButton(&host), progress, new QLabel(&host)},
                           JobPresenter::ProgressText::Count);
    host.show();
    test::HeldBackgroundJob held(&job);
    const std::string path = test::testDataPath("animations/folding_box").string();
    job.start([path](const TaskControl& control) {
        return std::make_shared<const LoadedAnimation>(loadAnimationForDisplay(path, control));
    });
    presenter.showStarted(QStringLiteral("Segmenting…"));
    QVERIFY(held.waitUntilHeld(kWaitMs));
    QTRY_VERIFY(progress->maximum() > 0);
    emit job.progressed(QStringLiteral("per-pose segments"), 0, 1);
    QCOMPARE(progress->maximum(), 0);
    QCOMPARE(progress->format(), QStringLiteral("per-pose segments…"));
    emit job.progressed(QStringLiteral("load"), 1, 3);
    QCOMPARE(progress->format(), QStringLiteral("load: %v / %m"));
    QSignalSpy finished(&job, &BackgroundJobBase::finished);
    held.release();
    QVERIFY(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kWaitMs));
}

void TestJobPresenter::skeletonPanelRunsCancelsAndRefuses()
{
    SkeletonPanel panel;
    panel.show();
    const Row row{child<QPushButton>(&panel, "runSkeletonButton"), child<QPushButton>(&panel, "cancelSkeletonButton"),
                  child<QProgressBar>(&panel, "skeletonProgressBar"), child<QLabel>(&panel, "skeletonStatusLabel")};
    QVERIFY(!row.run->isEnabled()); // no scene
    panel.setScene(std::make_shared<const LoadedScene>(loadScene(m_capsule.toStdString())));
    QVERIFY(row.run->isEnabled());
    child<QSpinBox>(&panel, "skeletonNodesSpinBox")->setValue(20);

    QVERIFY(runHeldAndCancel(panel.task(), row));
    QVERIFY(!panel.result());
    QCOMPARE(row.status->text(), SkeletonPanel::tr("Canceled."));

    QSignalSpy resultChanged(&panel, &SkeletonPanel::resultChanged);
    QVERIFY(clickAndWait(panel.task(), row.run));
    QCOMPARE(resultChanged.size(), 1);
    const std::shared_ptr<const SkeletonResult> result = panel.result();
    QVERIFY(result);
    QCOMPARE(result->kind, SkeletonRunKind::Full);
    QCOMPARE(result->options.heatConstant, panel.choices().heatConstant); // the form's value reaches the core
    QCOMPARE(result->options.extraction.targetNodes, 20);
    QVERIFY(result->rig.bones.size() >= 1);
    QCOMPARE(result->weights->vertexCount(), result->extraction->contracted.size());
    QVERIFY(result->rigQuality.nodesInside > 0.0);
    QVERIFY2(row.status->text().startsWith(QStringLiteral("Done: ")), qPrintable(row.status->text()));
    QVERIFY(!row.progress->isVisible());
    QVERIFY(row.run->isEnabled() && !row.cancel->isEnabled());

    // Another node count reuses the contraction (the rig-only re-run).
    child<QSpinBox>(&panel, "skeletonNodesSpinBox")->setValue(24);
    QVERIFY(clickAndWait(panel.task(), row.run));
    QCOMPARE(panel.result()->kind, SkeletonRunKind::RigOnly);
    QCOMPARE(panel.result()->extraction, result->extraction);

    panel.setScene(std::make_shared<const LoadedScene>(loadScene(m_openCapsule.toStdString())));
    QVERIFY(clickAndWait(panel.task(), row.run));
    QVERIFY(!panel.result());
    auto* error = child<QLabel>(&panel, "skeletonErrorLabel");
    QVERIFY(error->isVisible());
    QVERIFY2(error->text().startsWith(QStringLiteral("Not extracted: ")) &&
                 error->text().contains(QStringLiteral("open")),
             qPrintable(error->text()));
}

void TestJobPresenter::skinningPanelFitsAndCancels()
{
    SkinningPanel panel;
    panel.show();
    const Row row{child<QPushButton>(&panel, "fitSkinningButton"), child<QPushButton>(&panel, "cancelSkinningButton"),
                  child<QProgressBar>(&panel, "skinningProgressBar"), child<QLabel>(&panel, "skinningStatusLabel")};
    const std::shared_ptr<const LoadedAnimation> box = loadTestAnimation("folding_box");
    panel.setAnimation(box);
    panel.setSegmenterSettings(SegmentationChoices{}.segmenterSettings());
    SkinningChoices choices = panel.choices();
    choices.boneSource = BoneSource::GivenCount;
    choices.boneCount = 3;
    panel.setChoices(choices);
    QVERIFY(row.run->isEnabled());

    QVERIFY(runHeldAndCancel(panel.fitTask(), row));
    QVERIFY(!panel.session());
    QCOMPARE(row.status->text(), SkinningPanel::tr("Canceled."));

    QSignalSpy progressed(panel.fitTask(), &BackgroundJobBase::progressed);
    QVERIFY(clickAndWait(panel.fitTask(), row.run));
    QVERIFY(panel.session());
    const SkinningFit& fit = panel.session()->fit();
    QCOMPARE(fit.bones.count, 3u);
    QVERIFY(fit.search.has_value()); // segmented anew into the count
    QCOMPARE(fit.approximation.size(), box->animation->poseCount());
    QCOMPARE(fit.original.size(), box->animation->poseCount());
    QVERIFY(std::isfinite(fit.result.error.eRms));
    QSet<QString> stages;
    for (const QList<QVariant>& report : progressed)
        stages.insert(report.at(0).toString());
    QVERIFY2(stages.contains(QStringLiteral("reconstruction")), qPrintable(QStringList(stages.values()).join(',')));
    QVERIFY2(row.status->text().startsWith(QStringLiteral("Done: 3 bones")), qPrintable(row.status->text()));
    QVERIFY(!row.progress->isVisible());

    // More bones than vertices: the fit button refuses before any job runs.
    choices.boneCount = int(box->animation->vertexCount()) + 1;
    panel.setChoices(choices);
    QVERIFY(!row.run->isEnabled());
}

void TestJobPresenter::segmentationPanelRunsCancelsAndRefuses()
{
    SegmentationPanel panel;
    panel.show();
    const Row row{
        child<QPushButton>(&panel, "runSegmentationButton"), child<QPushButton>(&panel, "cancelSegmentationButton"),
        child<QProgressBar>(&panel, "segmentationProgressBar"), child<QLabel>(&panel, "segmentationStatusLabel")};
    panel.setAnimation(loadTestAnimation("folding_box"));
    QVERIFY(row.run->isEnabled());

    QVERIFY(runHeldAndCancel(panel.runTask(), row));
    QVERIFY(!panel.result());

    QVERIFY(clickAndWait(panel.runTask(), row.run));
    const std::shared_ptr<const SegmentationResult> result = panel.result();
    QVERIFY(result);
    QCOMPARE(result->variable.size(), result->segmenter->partitionedPoses().size()); // the panel's per-pose view
    QVERIFY(panel.shownLabeling());
    QVERIFY2(row.status->text().startsWith(QStringLiteral("Done: 3 poses")), qPrintable(row.status->text()));
    QVERIFY(!row.progress->isVisible());

    panel.setAnimation(loadTestAnimation("bar/bar_1.*"));
    QVERIFY(clickAndWait(panel.runTask(), row.run));
    QVERIFY(!panel.result());
    QVERIFY2(row.status->text().contains(QStringLiteral("the animation has 1 pose")), qPrintable(row.status->text()));
}

// In real-time mode the Run button reads "Stream poses", and the status line that tells
// the user which button to press says the same.
void TestJobPresenter::segmentationStatusNamesTheRunButton()
{
    SegmentationPanel panel;
    panel.show();
    auto* run = child<QPushButton>(&panel, "runSegmentationButton");
    auto* status = child<QLabel>(&panel, "segmentationStatusLabel");
    auto* mode = child<QComboBox>(&panel, "modeComboBox");
    QVERIFY(run && status && mode);
    panel.setAnimation(loadTestAnimation("folding_box"));
    QVERIFY2(status->text().contains(QStringLiteral("Press Run ")), qPrintable(status->text()));
    mode->setCurrentIndex(mode->findData(int(SegmentationMode::RealTime)));
    QCOMPARE(run->text(), QStringLiteral("Stream poses"));
    QVERIFY2(status->text().contains(QStringLiteral("Press Stream poses ")), qPrintable(status->text()));
    mode->setCurrentIndex(mode->findData(int(SegmentationMode::Global)));
    QCOMPARE(run->text(), QStringLiteral("Run"));
    QVERIFY2(status->text().contains(QStringLiteral("Press Run ")), qPrintable(status->text()));
}

TRIMLAB_WIDGET_TEST_MAIN(TestJobPresenter)
#include "tst_job_presenter.moc"
