#pragma once
/// \file
/// The busy progress dialog of a BackgroundJob (opening a project, exporting the
/// trimmed solid): window-modal, shown only when the work outlasts a short delay, its
/// Cancel button cancelling the task; and closing it again once the task reported.

#include <QPointer>
#include <QProgressDialog>
#include <QString>

class QWidget;

namespace trimlab::ui {

class BackgroundJobBase;

/// How long work runs before its progress dialog appears.
inline constexpr int kTaskProgressDelayMs = 400;

/// Closes `dialog` if open, then opens a new one over `parent` for `task`.
void openTaskProgress(QPointer<QProgressDialog>& dialog, QWidget* parent, BackgroundJobBase* task, const QString& title,
                      const QString& label);

/// Hides and deletes `dialog`, disconnected from everything first (hiding a progress
/// dialog emits canceled(), which must cancel nothing now); no-op when none is open.
void closeProgressDialog(QPointer<QProgressDialog>& dialog);

} // namespace trimlab::ui
