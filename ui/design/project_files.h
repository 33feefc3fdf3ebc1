#pragma once
/// \file
/// The designer's project files (.trimlab, core/timeline/project_file.h) in the window:
/// opening one off the UI thread (a busy progress dialog with Cancel after a short
/// delay), Save Project / Save Project As… (atomic; the camera and the static rule go
/// into the file's extras), and the prompt before unsaved changes would be lost. A
/// project that cannot be read is reported through failed(); nothing else changes.

#include "core/timeline/project_file.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <memory>

class QProgressDialog;
class QSettings;
class QWidget;

namespace trimlab::ui {

class BackgroundTask;
class DesignWorkspace;

class ProjectFiles : public QObject {
    Q_OBJECT
public:
    /// The file name suffix of project files (without the dot).
    static constexpr const char* kSuffix = "trimlab";
    /// What a saved project stores next to the history (the camera, the static rule).
    using ExtrasSource = std::function<timeline::ProjectExtras()>;

    ProjectFiles(QWidget* window, QSettings& settings, DesignWorkspace& workspace, ExtrasSource extras);
    ~ProjectFiles() override;

    [[nodiscard]] static bool isProjectPath(const QString& path);
    /// "TrimLab project (*.trimlab)".
    [[nodiscard]] static QString dialogFilter();

    /// Reads `path` off the UI thread; opened() or failed() follows (or nothing when
    /// canceled or superseded by a newer open()).
    void open(const QString& path);
    [[nodiscard]] bool isOpening() const;

    /// Saves to the session's project file, asking for one when it has none. Returns
    /// false when nothing was saved (canceled or failed: the failure is reported).
    bool save();
    /// Asks for a file, then saves there.
    bool saveAs();
    /// Saves the session to `path` atomically; on success the session is clean and its
    /// project path is `path`. False with the reason in `error` otherwise.
    bool saveTo(const QString& path, QString* error);
    /// When the session has unsaved changes, asks Save / Discard / Cancel. True when the
    /// caller may go on (saved, discarded, or nothing to save).
    bool maybeSave();

signals:
    void opened(std::shared_ptr<const trimlab::timeline::Project> project, const QString& path);
    void failed(const QString& path, const QString& message);
    void saved(const QString& path);

private:
    void finishOpen(bool succeeded, const QString& message);
    void closeProgress();

    QWidget* m_window;
    QSettings& m_settings;
    DesignWorkspace& m_workspace;
    ExtrasSource m_extras;
    BackgroundTask* m_task = nullptr;
    QPointer<QProgressDialog> m_progress;
    QString m_openPath;
    std::shared_ptr<timeline::Project> m_result;
};

} // namespace trimlab::ui
