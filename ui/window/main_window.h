#pragma once
/// \file
/// TrimLab's main window. It composes one workspace object per feature — each owns its
/// docks, actions and connections (docs/architecture.md):
/// - RenderWorkspace (render_panel/): the Render dock and the Frame statistics dock;
/// - AnimationWorkspace (animation/): the Timeline and Segmentation docks, with the
///   SkinningWorkspace (skinning/) and its dock;
/// - DesignWorkspace (design/): the Brush and Deformation timeline docks, Edit actions,
///   projects, autosave and recovery, history exports;
/// - SurfaceWorkspace (surface/): the Create menu, the Surface dock, Control Points (P);
/// - SkeletonWorkspace (skeleton/): the Skeleton dock;
/// - InspectWorkspace (inspect/): the Scene dock, Add Object, object drags.
/// What the window keeps is what they share: the viewport in the centre, the one thing
/// shown and how it gives way to the next (SceneSwitch, the features' SceneHost), the
/// menus, the title, the window state, and how the features' choices meet
/// (applyRenderChoices).
///
/// Every way of opening a scene — File ▸ Open…, Open Demo, Open Recent, drag and drop of
/// a file, the command line — goes through openSource(), which loads off the UI thread
/// (SceneLoader); a .trimlab project opens through the design feature's ProjectFiles.
/// Every way of opening a mesh animation — File ▸ Open Animation…, Open Recent
/// Animation, drag and drop of a folder — goes through openAnimation() (AnimationOpener:
/// progress and cancel); its rest pose then is the scene. A trimmable single-object mesh
/// shown starts a deformation history. A failed load shows a dialog naming the file and
/// the reason and keeps what is shown. If nothing was opened by the time the event loop
/// first runs, the window opens defaultSource(). Each file opened is a new document
/// (ui/common/document.h) with its own view settings; its unsaved changes are asked about
/// before they would be lost, and the title shows its name and marks them with a *.
///
/// Settings (every feature's choices but the document's view settings, recent files and
/// recent animations — two lists, since an animation is a folder or pattern as often as a
/// file —, the last directory, window geometry and dock state) persist in a QSettings: the
/// user's (organization and application "TrimLab"), or an INI file given to the
/// constructor, so tests never touch the user's settings. Without saved settings the window
/// starts with firstStartRenderChoices().

#include "ui/inspect/solid_export.h"

#include "core/catalog/scene_source.h"

#include <QMainWindow>
#include <QString>
#include <QStringList>

#include <memory>

class QDockWidget;
class QMenu;
class QSettings;

namespace trimlab::ui {

class AnimationOpener;
class AnimationWorkspace;
class CurrentDocument;
class DesignWorkspace;
class InspectWorkspace;
class MessageLog;
class RenderWorkspace;
class SceneLoader;
class SceneSwitch;
class SkeletonWorkspace;
class SurfaceWorkspace;
class OrientationAxes;
class SceneStatisticsDialog;
class ViewportWidget;
class WindowContext;
class Document;
struct LoadedAnimation;

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

    /// Opens `source` — a mesh file path, a .trimlab project or "demo:NAME" —
    /// asynchronously, after asking about unsaved changes (nothing happens when the user
    /// cancels). The result arrives as sceneLoaded() or sceneLoadFailed() (with its
    /// dialog); a newer call or Cancel in the progress dialog discards a pending load.
    void openSource(const QString& source);
    /// Opens the mesh animation `source` — a folder, a pattern (dir/mesh_*.obj,
    /// dir/mesh_%04d.obj.gz) or a .gltf/.glb file — asynchronously, with progress and
    /// cancel. The result arrives as animationLoaded() or sceneLoadFailed() (with its
    /// dialog); a newer openSource()/openAnimation() or Cancel discards a pending one.
    void openAnimation(const QString& source);
    /// Writes the viewport's last frame (color, at the frame's pixel size) as a PNG file.
    /// Returns false with the reason in `error` when there is no frame or writing fails.
    bool exportImage(const QString& path, QString* error = nullptr);

    /// True while a scene or an animation is being opened.
    [[nodiscard]] bool isLoading() const;
    /// The scene shown (nullptr before the first successful load).
    [[nodiscard]] std::shared_ptr<const LoadedScene> scene() const;
    [[nodiscard]] ViewportWidget* viewport() const { return m_viewport; }
    [[nodiscard]] SceneLoader* sceneLoader() const;
    [[nodiscard]] AnimationOpener* animationOpener() const;
    [[nodiscard]] QStringList recentFiles() const;
    [[nodiscard]] QStringList recentAnimations() const;
    /// The document shown: its project file, view settings, undo stack, modified state
    /// (nullptr before the first file is shown).
    [[nodiscard]] Document* document() const;
    /// The open animation (nullptr while a mesh or demo is shown).
    [[nodiscard]] std::shared_ptr<const LoadedAnimation> animation() const;

    /// The feature workspaces (their panels and actions: renderWorkspace()->panel(), …).
    [[nodiscard]] RenderWorkspace* renderWorkspace() const { return m_render; }
    [[nodiscard]] InspectWorkspace* inspectWorkspace() const { return m_inspect; }
    [[nodiscard]] SolidExport* solidExport() const { return m_solidExport; }
    [[nodiscard]] AnimationWorkspace* animationWorkspace() const { return m_animation; }
    [[nodiscard]] DesignWorkspace* designWorkspace() const { return m_design; }
    [[nodiscard]] SurfaceWorkspace* surfaceWorkspace() const { return m_surface; }
    [[nodiscard]] SkeletonWorkspace* skeletonWorkspace() const { return m_skeleton; }
    /// Every message shown (status lines and boxes); View ▸ Messages lists it.
    [[nodiscard]] MessageLog* messageLog() const { return m_log; }
    [[nodiscard]] QDockWidget* messagesDock() const { return m_messagesDock; }

signals:
    /// A scene is shown; `source` as given to openSource().
    void sceneLoaded(const QString& source);
    /// An animation is shown (its rest pose as the scene); `source` as given to
    /// openAnimation().
    void animationLoaded(const QString& source);
    /// Loading `source` (a scene or an animation) failed with `message`; the previous
    /// scene or animation is still shown.
    void sceneLoadFailed(const QString& source, const QString& message);
    /// InspectWorkspace::addObject(`source`) appended its objects to the scene shown.
    void objectAdded(const QString& source);

protected:
    void closeEvent(QCloseEvent* event) override;
    /// A click on the status bar opens the Messages dock.
    bool eventFilter(QObject* watched, QEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    [[nodiscard]] SolidExport::Shown shownSolid() const;
    MainWindow(std::unique_ptr<QSettings> settings, QWidget* parent);

    void createCentralView();
    void createWorkspaces();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createMessagesDock();
    void createHelpMenu();
    void addViewPresets(QMenu* view);
    void connectWorkspaces();
    void restoreSettings();
    void saveWindowState();
    void showOpenDialog();
    void showOpenAnimationDialog();
    void showExportDialog();
    void showAbout();
    void showSceneStatistics();
    void openDefaultIfNothingRequested();
    void applyRenderChoices();
    void updateTitle();

    std::unique_ptr<QSettings> m_settings;
    ViewportWidget* m_viewport = nullptr;
    OrientationAxes* m_axes = nullptr;             ///< the gizmo over the view
    SceneStatisticsDialog* m_statistics = nullptr; ///< View ▸ Mesh Statistics, made when first asked
    /// Owns the viewport when OpenGL is unavailable and it is kept out of the window.
    std::unique_ptr<ViewportWidget> m_detachedViewport;
    CurrentDocument* m_document = nullptr; ///< the document shown (ui/common/document.h)
    SceneSwitch* m_switch = nullptr;
    std::unique_ptr<WindowContext> m_context;
    RenderWorkspace* m_render = nullptr;
    AnimationWorkspace* m_animation = nullptr;
    DesignWorkspace* m_design = nullptr;
    SurfaceWorkspace* m_surface = nullptr;
    SkeletonWorkspace* m_skeleton = nullptr;
    InspectWorkspace* m_inspect = nullptr;
    SolidExport* m_solidExport = nullptr;
    MessageLog* m_log = nullptr;
    QDockWidget* m_messagesDock = nullptr;
};

} // namespace trimlab::ui
