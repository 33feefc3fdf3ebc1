#pragma once
/// \file
/// The designer's project files (.trimlab, core/timeline/project_file.h) in the window:
/// opening one off the UI thread (a busy progress dialog with Cancel after a short
/// delay), Save Project / Save Project As… (atomic; the camera and the static rule go
/// into the file's extras) of the deformation history or, when none is shown, of the
/// scene with its objects, placements and CSG (a scene project), and the prompt before
/// unsaved changes of a history would be lost. A
/// project that cannot be read is reported through failed(); nothing else changes.

#include "core/catalog/scene_source.h"
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
    /// The scene the Scene panel shows with its CSG settings: what Save Project writes as a
    /// scene project (format version 3) when no deformation history is shown. A null
    /// scene when there is nothing to save that way (none, or an animation's rest pose).
    struct ShownScene {
        std::shared_ptr<const LoadedScene> scene;
        CsgSettings csg;
        /// An assembly of several objects with changes no file holds (maybeSaveScene asks).
        bool unsaved = false;
        /// Called once the scene is saved.
        std::function<void()> markSaved;
    };
    using SceneSource = std::function<ShownScene()>;

    ProjectFiles(QWidget* window, QSettings& settings, DesignWorkspace& workspace, ExtrasSource extras);
    ~ProjectFiles() override;

    [[nodiscard]] static bool isProjectPath(const QString& path);
    /// "TrimLab project (*.trimlab)".
    [[nodiscard]] static QString dialogFilter();

    /// Reads `path` off the UI thread; opened() or failed() follows (or nothing when
    /// canceled or superseded by a newer open()).
    void open(const QString& path);
    [[nodiscard]] bool isOpening() const;

    void setSceneSource(SceneSource source) { m_sceneSource = std::move(source); }
    /// A scene is shown: opened from the scene project `path` (Save writes there), or from
    /// elsewhere ("": Save asks for a file). Save Project's enabled state may change.
    void sceneShown(const QString& path);
    /// There is a deformation history or a scene to save.
    [[nodiscard]] bool canSave() const;

    /// Saves the history to the session's project file, or the scene (without a session)
    /// to its scene project, asking for a file when there is none. Returns false when
    /// nothing was saved (canceled or failed: the failure is reported).
    bool save();
    /// Asks for a file, then saves there.
    bool saveAs();
    /// Saves the session to `path` atomically (then the session is clean and its project
    /// path is `path`), or without a session the shown scene as a scene project. False
    /// with the reason in `error` otherwise.
    bool saveTo(const QString& path, QString* error);
    /// When the session has unsaved changes, asks Save / Discard / Cancel. True when the
    /// caller may go on (saved, discarded, or nothing to save).
    bool maybeSave();
    /// The same for a scene of several objects without a session (ShownScene::unsaved),
    /// before it is replaced or the window closes.
    bool maybeSaveScene();

signals:
    void opened(std::shared_ptr<const trimlab::timeline::Project> project, const QString& path);
    void failed(const QString& path, const QString& message);
    void saved(const QString& path);
    /// canSave() may have changed.
    void saveableChanged();

private:
    void finishOpen(bool succeeded, const QString& message);
    [[nodiscard]] QString currentPath() const;
    bool saveSceneTo(const QString& path, QString* error);
    bool askToSave(const QString& text, const QString& question, const QString& name);
    void closeProgress();

    QWidget* m_window;
    QSettings& m_settings;
    DesignWorkspace& m_workspace;
    ExtrasSource m_extras;
    SceneSource m_sceneSource;
    QString m_scenePath; ///< the shown scene's project file, "" when it has none
    BackgroundTask* m_task = nullptr;
    QPointer<QProgressDialog> m_progress;
    QString m_openPath;
    std::shared_ptr<timeline::Project> m_result;
};

} // namespace trimlab::ui
