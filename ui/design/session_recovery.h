#pragma once
/// \file
/// Crash recovery in the window: owns the Autosave of the design session and, when the
/// window starts, offers the work of a TrimLab that died (autosave.h). Recovering opens
/// the autosaved history like a project and then gives it back its own identity: the
/// project file it belonged to (or none) and "modified", so the user saves it where it
/// belongs. The offer is a window-modal box shown without blocking (open(), not exec()),
/// one session at a time, newest first.

#include "ui/design/autosave.h"

#include <QMessageBox>
#include <QObject>
#include <QPointer>

#include <memory>
#include <optional>

class QSettings;
class QWidget;

namespace trimlab::ui {

class DesignWorkspace;

class SessionRecovery : public QObject {
    Q_OBJECT
public:
    /// Settings: "recovery/directory" (default Autosave::defaultDirectory()) and
    /// "recovery/intervalMinutes" (default Autosave::kDefaultIntervalMinutes; 0 = off).
    SessionRecovery(QWidget* window, QSettings& settings, DesignWorkspace& workspace, ProjectFiles& projectFiles);
    ~SessionRecovery() override;

    [[nodiscard]] Autosave& autosave() { return *m_autosave; }
    /// Shows the offer for the newest recoverable session, if any.
    void offer();
    /// The offer on screen (nullptr when none).
    [[nodiscard]] QMessageBox* offerBox() const { return m_box; }
    /// Opens `session` through ProjectFiles; adoptRecovered() finishes it.
    void recover(const RecoverableSession& session);
    /// Called by the window once ProjectFiles opened `path`: when it is the session being
    /// recovered, the document gets its original project file and name back and is marked
    /// modified, the recovery files are deleted and autosave covers it again. Returns
    /// false for any other project.
    bool adoptRecovered(const QString& path);

signals:
    /// The recovered history is shown; `originalPath` "" for an untitled project.
    void recovered(const QString& originalPath);

private:
    void onOfferFinished(const RecoverableSession& session, int role);

    QWidget* m_window;
    DesignWorkspace& m_workspace;
    ProjectFiles& m_projectFiles;
    QString m_directory;
    std::unique_ptr<Autosave> m_autosave;
    QPointer<QMessageBox> m_box;
    std::optional<RecoverableSession> m_pending;
};

} // namespace trimlab::ui
