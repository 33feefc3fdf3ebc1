#include "ui/common/task_progress_dialog.h"

#include "ui/common/background_job.h"

namespace trimlab::ui {

void openTaskProgress(QPointer<QProgressDialog>& dialog, QWidget* parent, BackgroundJobBase* task, const QString& title,
                      const QString& label)
{
    closeProgressDialog(dialog);
    dialog = new QProgressDialog(label, QProgressDialog::tr("Cancel"), 0, 0, parent);
    dialog->setWindowTitle(title);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(kTaskProgressDelayMs);
    QObject::connect(dialog, &QProgressDialog::canceled, task, &BackgroundJobBase::cancel);
    dialog->setValue(0);
}

void closeProgressDialog(QPointer<QProgressDialog>& dialog)
{
    if (!dialog)
        return;
    dialog->disconnect();
    dialog->hide();
    dialog->deleteLater();
    dialog.clear();
}

} // namespace trimlab::ui
