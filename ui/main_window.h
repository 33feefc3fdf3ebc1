#pragma once
/// \file
/// TrimLab's main window: the viewport in the centre, the Render panel in a dock, the
/// frame statistics in a second dock ("Frame statistics": the last frame's numbers,
/// overflow advice, and the per-method frame-time chart) and in the status bar, and the
/// File / View / Help menus.
///
/// Every way of opening a scene — File ▸ Open…, Open Demo, Open Recent, drag and drop,
/// the command line — goes through openSource(), which loads off the UI thread
/// (SceneLoader). A failed load shows a dialog naming the file and the reason and keeps
/// the current scene. If nothing was opened by the time the event loop first runs, the
/// window opens defaultSource().
///
/// Settings (render choices, recent files, last directory, window geometry and dock
/// state) persist in a QSettings: the user's (organization and application "TrimLab"),
/// or an INI file given to the constructor, so tests never touch the user's settings.
/// Without saved settings the window starts with firstStartRenderChoices().

#include "mfr/fragment_method.h"
#include "recent_files.h"
#include "scene/scene_source.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QString>

#include <memory>

class QDockWidget;
class QMenu;
class QSettings;

namespace trimlab::ui {

class FrameStatsLabels;
class FrameStatsPanel;
class MethodTimingPanel;
class RenderPanel;
class SceneLoader;
class ViewportWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Uses the user's settings.
    explicit MainWindow(QWidget* parent = nullptr);
    /// Uses the INI file `settingsFile` (created on demand) instead of the user's settings.
    explicit MainWindow(const QString& settingsFile, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// "demo:pushed-sphere": what a new window shows.
    [[nodiscard]] static QString defaultSource();

    /// Opens `source` — a mesh file path or "demo:NAME" — asynchronously. The result
    /// arrives as sceneLoaded() or sceneLoadFailed() (with its dialog); a newer call or
    /// Cancel in the progress dialog discards a pending load.
    void openSource(const QString& source);
    /// Writes the viewport's last frame (color, at the frame's pixel size) as a PNG file.
    /// Returns false with the reason in `error` when there is no frame or writing fails.
    bool exportImage(const QString& path, QString* error = nullptr);

    [[nodiscard]] bool isLoading() const;
    /// The scene shown (nullptr before the first successful load).
    [[nodiscard]] std::shared_ptr<const LoadedScene> scene() const { return m_scene; }
    [[nodiscard]] ViewportWidget* viewport() const { return m_viewport; }
    [[nodiscard]] RenderPanel* renderPanel() const { return m_panel; }
    [[nodiscard]] FrameStatsPanel* frameStatsPanel() const { return m_statsPanel; }
    [[nodiscard]] MethodTimingPanel* methodTimingPanel() const { return m_timingPanel; }
    [[nodiscard]] SceneLoader* sceneLoader() const { return m_loader; }
    [[nodiscard]] QStringList recentFiles() const { return m_recent.paths(); }

signals:
    /// A scene is shown; `source` as given to openSource().
    void sceneLoaded(const QString& source);
    /// Loading `source` failed with `message`; the previous scene is still shown.
    void sceneLoadFailed(const QString& source, const QString& message);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    MainWindow(std::unique_ptr<QSettings> settings, QWidget* parent);

    void createCentralView();
    void createDock();
    void createStatsDock();
    void createFileMenu();
    void createViewMenu();
    void createHelpMenu();
    void rebuildRecentMenu();
    void connectParts();
    void restoreSettings();
    void saveWindowState();

    void showOpenDialog();
    void showExportDialog();
    void showAbout();
    void openRecent(const QString& path);
    void openDefaultIfNothingRequested();
    void onSceneLoaded(std::shared_ptr<const LoadedScene> loaded);
    void onLoadFailed(const QString& source, const QString& message);
    void onRenderError(const QString& message);
    void applyRenderChoices();
    void refreshMemoryEstimate();
    void showFrameStatistics();
    void chooseMethod(render::FragmentMethodKind method);
    void chooseK(int k);
    void showMessage(QMessageBox::Icon icon, const QString& title, const QString& text, const QString& details);
    void updateTitle();

    std::unique_ptr<QSettings> m_settings;
    ViewportWidget* m_viewport = nullptr;
    /// Owns the viewport when OpenGL is unavailable and it is kept out of the window.
    std::unique_ptr<ViewportWidget> m_detachedViewport;
    RenderPanel* m_panel = nullptr;
    QDockWidget* m_dock = nullptr;
    FrameStatsPanel* m_statsPanel = nullptr;
    MethodTimingPanel* m_timingPanel = nullptr;
    QDockWidget* m_statsDock = nullptr;
    FrameStatsLabels* m_statsLabels = nullptr;
    SceneLoader* m_loader = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    RecentFiles m_recent;
    std::shared_ptr<const LoadedScene> m_scene;
    bool m_openRequested = false;
};

} // namespace trimlab::ui
