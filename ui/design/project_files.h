#pragma once
/// \file
/// The designer's project files (.trimlab, core/timeline/project_file.h) in the window:
/// opening one off the UI thread (a busy progress dialog with Cancel after a short
/// delay), Save Project / Save Project As… (atomic; the camera and the static rule go
/// into the file's extras, with the rest of the document's view settings) of the
/// deformation history or, when none is shown, of the scene with its objects, placements
/// and CSG (a scene project), and the prompt before the document's unsaved changes would
/// be lost. What is saved where, and whether there is anything unsaved, is the document's
/// (ui/common/document.h): a save marks it saved. A project that cannot be read is
/// reported through failed(); nothing else changes.

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

template <class T>
class BackgroundJob;
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
    /// There is a deformation history or a scene to save.
    [[nodiscard]] bool canSave() const;

    /// Saves the history, or the scene (without a session), to the document's project
    /// file, asking for a file when it has none. Returns false when nothing was saved
    /// (canceled or failed: the failure is reported).
    bool save();
    /// Asks for a file, then saves there.
    bool saveAs();
    /// writeTo(`path`), then the document is saved there (clean, its file `path`). False
    /// with the reason in `error` otherwise.
    bool saveTo(const QString& path, QString* error);
    /// Writes the document shown to `path` atomically — the history with the session, else
    /// the scene as a scene project — without changing what the document knows (autosave
    /// writes its copies this way). Throws std::runtime_error with the reason.
    void writeTo(const QString& path) const;
    /// When the document has unsaved changes (a design's history, a scene's objects,
    /// placements or CSG), asks Save / Discard / Cancel. True when the caller may go on
    /// (saved, discarded, or nothing to save).
    bool maybeSave();

signals:
    void opened(std::shared_ptr<const trimlab::timeline::Project> project, const QString& path);
    void failed(const QString& path, const QString& message);
    void saved(const QString& path);
    /// canSave() may have changed.
    void saveableChanged();

private:
    void finishOpen(bool succeeded, const QString& message);
    [[nodiscard]] QString currentPath() const;
    bool askToSave(const QString& text, const QString& question, const QString& name);
    void closeProgress();

    QWidget* m_window;
    QSettings& m_settings;
    DesignWorkspace& m_workspace;
    ExtrasSource m_extras;
    SceneSource m_sceneSource;
    BackgroundJob<std::shared_ptr<const timeline::Project>>* m_task = nullptr; ///< reads a project
    QPointer<QProgressDialog> m_progress;
    QString m_openPath;
};

} // namespace trimlab::ui
