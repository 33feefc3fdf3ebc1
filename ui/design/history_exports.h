#pragma once
/// \file
/// What leaves or enters a deformation history besides project files
/// (core/timeline/frame_export.h, stroke_script.h, stroke_replay.h): File ▸ Export ▸
/// "Frames as OBJ sequence…" and "Deformation as glTF (morph targets)…", File ▸ "Save
/// stroke script…", and File ▸ "Replay stroke script…", which replays a script on the
/// session's base mesh off the UI thread (progress per stroke, Cancel) and shows the
/// result as a new session with a clean undo stack. A script that cannot be read or
/// replayed is reported through problem(); the session shown stays as it was.

#include <QObject>
#include <QPointer>
#include <QString>

#include <memory>

class QProgressDialog;
class QSettings;
class QWidget;

namespace trimlab::timeline {
class Timeline;
}

namespace trimlab::ui {

template <class T>
class BackgroundJob;
class DesignWorkspace;

class HistoryExports : public QObject {
    Q_OBJECT
public:
    HistoryExports(QWidget* window, QSettings& settings, DesignWorkspace& workspace);
    ~HistoryExports() override;

    void showExportObjDialog();
    void showExportGltfDialog();
    void showSaveScriptDialog();
    void showReplayDialog();

    /// Writes every frame as `directory`/`baseName`_NNNN.obj. False with the reason in
    /// `error` when nothing or not everything was written.
    bool exportObjSequence(const QString& directory, const QString& baseName, QString* error);
    /// Writes the morph-target glTF (.glb binary, else .gltf) at `fps` frames per second.
    bool exportGltf(const QString& path, double fps, QString* error);
    bool saveStrokeScript(const QString& path, QString* error);
    /// Starts replaying the script at `path` on the session's base mesh; replayed() or
    /// problem() follows (nothing when canceled).
    void replay(const QString& path);
    [[nodiscard]] bool isReplaying() const;
    /// The replay's progress dialog while one runs (nullptr otherwise).
    [[nodiscard]] QProgressDialog* progressDialog() const;

    /// The frames per second glTF exports use (the Deformation timeline's).
    void setFps(int fps) { m_fps = fps; }

signals:
    /// The replayed history is now the session.
    void replayed(const QString& path);
    void problem(const QString& title, const QString& text, const QString& details);
    void statusMessage(const QString& message);

private:
    [[nodiscard]] QString suggestedPath(const QString& suffix) const;
    /// `result`: the replayed history, or nullptr when the replay failed with `message`.
    void finishReplay(std::shared_ptr<timeline::Timeline> result, const QString& message);
    void closeProgress();

    QWidget* m_window;
    QSettings& m_settings;
    DesignWorkspace& m_workspace;
    BackgroundJob<std::shared_ptr<timeline::Timeline>>* m_task; ///< the replay
    QPointer<QProgressDialog> m_progress;
    QString m_replayPath;
    int m_fps = 24;
};

} // namespace trimlab::ui
