#pragma once
/// \file
/// Autosave and crash recovery for the document shown (ui/common/document.h). While it has
/// unsaved changes, it is written every few minutes (and on demand) the way Save Project
/// writes it (ProjectFiles::writeTo: a design's history, or a scene project) into the
/// recovery folder, as `session-<pid>.trimlab` beside a small `session-<pid>.json` (the
/// project file the document belongs to, when it was saved, and the name it had).
/// A `session-<pid>.lock` (QLockFile) is held for as long as this window lives, so a
/// recovery file whose lock can be taken belongs to a TrimLab that died: that is what
/// recoverableSessions() offers. A normal end (the Autosave destroyed, the work saved
/// or the session closed) removes the files.
///
/// Writes are atomic (core/io/atomic_write.h): a crash during an autosave leaves
/// the previous autosave intact.

#include "ui/design/project_files.h"

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>

#include <memory>

class QLockFile;
class QTimer;

namespace trimlab::ui {

class DesignWorkspace;

/// The work of a TrimLab that did not end normally.
struct RecoverableSession {
    QString projectFile;  ///< the autosaved .trimlab in the recovery folder
    QString infoFile;     ///< its .json companion
    QString lockFile;     ///< its (stale) lock
    QString originalPath; ///< the project the work belonged to ("" when never saved)
    QString name;         ///< the document's name then ("" when unknown)
    QDateTime savedAt;    ///< when it was autosaved (invalid when unknown)
};

class Autosave : public QObject {
    Q_OBJECT
public:
    /// The default folder: <AppLocalDataLocation>/recovery.
    [[nodiscard]] static QString defaultDirectory();
    /// Default interval between autosaves.
    static constexpr int kDefaultIntervalMinutes = 3;

    /// Starts watching the document of `workspace`, written through `files`; creates
    /// `directory` and takes this process's lock there (when either fails, autosave stays
    /// off and lastError() says why).
    Autosave(DesignWorkspace& workspace, const ProjectFiles& files, QString directory, QObject* parent = nullptr);
    ~Autosave() override;

    /// 0 turns the timer off (saveNow() still works).
    void setIntervalMinutes(int minutes);
    [[nodiscard]] int intervalMinutes() const { return m_intervalMinutes; }

    /// Writes the document now when it has changes the last autosave does not hold; true
    /// when a file was written. Removes the recovery files when there is nothing unsaved.
    bool saveNow();
    /// Removes this process's recovery files (the work was saved or dropped).
    void clear();

    [[nodiscard]] QString recoveryProjectPath() const;
    [[nodiscard]] const QString& directory() const { return m_directory; }
    [[nodiscard]] const QString& lastError() const { return m_lastError; }

    /// Recovery files in `directory` whose TrimLab is gone (their lock is stale), newest
    /// first. Never lists this process's own files.
    [[nodiscard]] static QList<RecoverableSession> recoverableSessions(const QString& directory);
    /// Deletes a recoverable session's files.
    static void discard(const RecoverableSession& session);

signals:
    void autosaved(const QString& path);
    void failed(const QString& message);

private:
    [[nodiscard]] QString sessionFile(const QString& suffix) const;
    void onModifiedChanged(bool modified);

    DesignWorkspace& m_workspace;
    const ProjectFiles& m_files;
    QString m_directory;
    std::unique_ptr<QLockFile> m_lock;
    QTimer* m_timer;
    int m_intervalMinutes = kDefaultIntervalMinutes;
    quint64 m_savedRevision = 0;
    const void* m_savedDocument = nullptr;
    QString m_lastError;
};

} // namespace trimlab::ui
