#pragma once
/// \file
/// What a panel shows of its one long job (the Skeleton, Skinning and Segmentation
/// panels): the Run / Cancel row (run_cancel_row.h), the progress bar and the status line,
/// kept in one protocol for every such panel:
/// - started: a busy bar until the first report, then the running stage's name and
///   progress (a stage of one step keeps the busy bar, with its name);
/// - Cancel: the job is asked to stop and the status says "Canceling…" until it ends;
///   Cancel stays disabled from then on;
/// - ended (succeeded, failed or canceled): the bar hides before the panel's own handlers
///   of those signals run — construct the presenter before connecting them — so they only
///   write their status and show their result;
/// - Run is enabled while idle and the panel can run; Cancel while the job runs.
/// Late progress reports of a job that has ended are dropped. The presenter holds no
/// algorithm and no result: a test drives it, with its panel or alone, without a window.

#include <QObject>
#include <QString>

class QLabel;
class QProgressBar;
class QPushButton;

namespace trimlab::ui {

class BackgroundJobBase;

class JobPresenter : public QObject {
    Q_OBJECT
public:
    /// How the bar writes progress: "stage: 42%" or "stage: 3 / 10".
    enum class ProgressText { Percent, Count };

    struct Widgets {
        QPushButton* run = nullptr;
        QPushButton* cancel = nullptr;
        QProgressBar* progress = nullptr;
        QLabel* status = nullptr;
    };

    /// Presents `job` in `widgets` (none of them owned); hides the bar.
    JobPresenter(BackgroundJobBase* job, const Widgets& widgets, ProgressText text, QObject* parent = nullptr);

    [[nodiscard]] BackgroundJobBase* job() const { return m_job; }
    /// After the panel started the job: a busy bar and `status`.
    void showStarted(const QString& status);
    /// Cancel's click: asks the running job to stop and says so; false (nothing done)
    /// when the job is idle.
    bool cancel();
    /// Enables Run when `canRun` and the job is idle, Cancel while it runs and has not
    /// been asked to stop — or while `otherWork` runs that Cancel also stops (a stream).
    void updateRow(bool canRun, bool otherWork = false) const;
    void setStatus(const QString& text) const;

private:
    void showProgress(const QString& stage, qint64 done, qint64 total);
    void hideProgress();

    BackgroundJobBase* m_job;
    Widgets m_widgets;
    ProgressText m_text;
};

} // namespace trimlab::ui
