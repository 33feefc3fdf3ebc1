#pragma once
/// \file
/// TrimLab's main window: the viewport in the centre, the Render panel in a dock, the
/// frame statistics in a second dock ("Frame statistics": the last frame's numbers,
/// overflow advice, and the per-method frame-time chart) and in the status bar, the
/// Segmentation panel (tabbed with the Render panel) and the Timeline (at the bottom,
/// shown while an animation is open), and the File / View / Help menus.
///
/// Every way of opening a scene — File ▸ Open…, Open Demo, Open Recent, drag and drop of
/// a file, the command line — goes through openSource(), which loads off the UI thread
/// (SceneLoader). Every way of opening a mesh animation — File ▸ Open Animation…, Open
/// Recent Animation, drag and drop of a folder — goes through openAnimation()
/// (AnimationOpener: progress and cancel). The animation's rest pose then is the scene
/// (one object; the trim controls apply as for a mesh), the Timeline plays its poses in
/// the viewport and the Segmentation panel segments it and colors it by segment; the
/// Skinning panel (a dock tabbed with it, shown while an animation is open) fits a
/// skinning with the segments as bones, and what it shows — the approximation's poses or
/// the error heat map — takes the place of the original poses and segment colors. The
/// Skeleton dock (tabbed with the Render panel; main_window_skeleton.cpp) extracts the
/// skeleton of a shown one-object mesh, shows its stages and poses it. A
/// failed load shows a dialog naming the file and the reason and keeps the current scene
/// or animation. If nothing was opened by the time the event loop first runs, the window
/// opens defaultSource().
///
/// The designer workflow (docs/designer-workflow.md): a trimmable single-object mesh
/// shown starts a deformation history (DesignWorkspace); the Brush dock and the brush tool
/// (Edit ▸ Brush, B) deform it, the Deformation timeline dock scrubs and plays it and
/// starts sets (N), Edit ▸ Undo/Redo undo strokes, sets and rules, and File ▸ Save Project
/// (Ctrl+S) / Save Project As… write .trimlab projects, which Open, Open Recent and drag
/// and drop open again. File ▸ Export ▸ writes the frames (OBJ sequence, glTF morph
/// targets); File ▸ Save/Replay Stroke Script record and replay strokes. Unsaved changes
/// are asked about before they would be lost, and the title marks them with a *.
///
/// Editable surfaces (main_window_surface.cpp, thesis 8.2): Create ▸ NURBS ▸ Sphere /
/// Torus / Tube / Patch and Create ▸ Subdivision Surface ▸ a built-in cage or From Cage
/// File… start a design session whose base mesh is the surface's tessellation (asking
/// about unsaved changes first); so do surface projects and the surface demos. The
/// control net is drawn over the view, Edit ▸ Control Points (P) picks and drags its
/// points (the brush moves them too), and the Surface dock shows and changes the
/// density, degree, level, scheme and mode (a rebuild: a new history) and moves the
/// selection along its normal.
///
/// Interior inspection (main_window_inspect.cpp): the Render panel's clipping planes (up
/// to six, a box), capping and highlighting; the Scene dock (scene_panel.h, tabbed with
/// the Render panel) lists the objects, edits their transforms, rules and the CSG
/// expression through an InspectScene, whose undo stack joins the Edit menu's undo
/// group (the stack last edited — the scene's or a design session's — is the one Undo
/// acts on); File ▸ Add Object… (addObject()) loads a mesh into the scene shown as one
/// more object, off the UI thread like opening. The status bar counts highlighted
/// (colliding, coplanar) pixels.
///
/// Settings (render choices, segmentation choices, playback, recent files and recent
/// animations — two lists, since an animation is a folder or pattern as often as a
/// file —, last directory, window geometry and dock state) persist in a QSettings: the
/// user's (organization and application "TrimLab"), or an INI file given to the
/// constructor, so tests never touch the user's settings. Without saved settings the
/// window starts with firstStartRenderChoices().

#include "mfr/fragment_method.h"
#include "recent_files.h"
#include "scene/scene_source.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QString>

#include <memory>

namespace trimlab::timeline {
struct Project;
struct ProjectExtras;
}
namespace trimlab {
struct SubdivisionCage;
struct SurfaceDefinition;
}

class QAction;
class QDockWidget;
class QMenu;
class QSettings;
class QToolBar;

namespace trimlab::ui {

class AnimationOpener;
class BrushPanel;
class DeformationTimelinePanel;
class DesignWorkspace;
class HistoryExports;
class InspectScene;
class ScenePanel;
class ProjectFiles;
class FrameStatsLabels;
class FrameStatsPanel;
class MethodTimingPanel;
class RenderPanel;
class SceneLoader;
class SegmentationPanel;
class SessionRecovery;
class SkeletonPanel;
class SkinningPanel;
class SurfacePanel;
class TimelinePanel;
enum class NurbsPrimitive;
class ViewportWidget;
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
    /// Loads the mesh file (or "demo:NAME") `source` off the UI thread and appends its
    /// objects to the scene shown, keeping the camera (File ▸ Add Object…). Asks about
    /// unsaved design changes first (the scene stops being a single designed object).
    /// objectAdded() or sceneLoadFailed() (with its dialog) follows; without a scene, or
    /// while an animation is shown, a dialog explains and nothing is loaded.
    void addObject(const QString& source);
    /// Writes the viewport's last frame (color, at the frame's pixel size) as a PNG file.
    /// Returns false with the reason in `error` when there is no frame or writing fails.
    bool exportImage(const QString& path, QString* error = nullptr);

    /// True while a scene or an animation is being opened.
    [[nodiscard]] bool isLoading() const;
    /// The scene shown (nullptr before the first successful load).
    [[nodiscard]] std::shared_ptr<const LoadedScene> scene() const { return m_scene; }
    [[nodiscard]] ViewportWidget* viewport() const { return m_viewport; }
    [[nodiscard]] RenderPanel* renderPanel() const { return m_panel; }
    [[nodiscard]] FrameStatsPanel* frameStatsPanel() const { return m_statsPanel; }
    [[nodiscard]] MethodTimingPanel* methodTimingPanel() const { return m_timingPanel; }
    [[nodiscard]] SceneLoader* sceneLoader() const { return m_loader; }
    /// The scene's edits (transforms, CSG) and the Scene dock's panel.
    [[nodiscard]] InspectScene* inspectScene() const { return m_inspect; }
    [[nodiscard]] ScenePanel* scenePanel() const { return m_scenePanel; }
    [[nodiscard]] QStringList recentFiles() const { return m_recent.paths(); }
    /// The open animation (nullptr while a mesh or demo is shown).
    [[nodiscard]] std::shared_ptr<const LoadedAnimation> animation() const { return m_animation; }
    [[nodiscard]] AnimationOpener* animationOpener() const { return m_animationOpener; }
    [[nodiscard]] TimelinePanel* timelinePanel() const { return m_timeline; }
    [[nodiscard]] SegmentationPanel* segmentationPanel() const { return m_segmentation; }
    [[nodiscard]] SkinningPanel* skinningPanel() const { return m_skinning; }
    /// The Skeleton dock's panel (skeleton extraction, posing and export on the mesh shown).
    [[nodiscard]] SkeletonPanel* skeletonPanel() const { return m_skeleton; }
    [[nodiscard]] QStringList recentAnimations() const { return m_recentAnimations.paths(); }
    [[nodiscard]] DesignWorkspace* designWorkspace() const { return m_design; }
    [[nodiscard]] BrushPanel* brushPanel() const { return m_brushPanel; }
    [[nodiscard]] DeformationTimelinePanel* deformationTimelinePanel() const { return m_deformationPanel; }
    [[nodiscard]] ProjectFiles* projectFiles() const { return m_projectFiles; }
    /// Autosave of the design session and the offer to recover a crashed one.
    [[nodiscard]] SessionRecovery* sessionRecovery() const { return m_recovery; }
    [[nodiscard]] HistoryExports* historyExports() const { return m_exports; }
    /// Edit ▸ Brush (B, checkable) and Edit ▸ New Set (N).
    [[nodiscard]] QAction* brushAction() const { return m_brushAction; }
    [[nodiscard]] QAction* newSetAction() const { return m_newSetAction; }
    /// Edit ▸ Control Points (P, checkable; exclusive with the brush).
    [[nodiscard]] QAction* controlPointsAction() const { return m_controlPointsAction; }
    /// The Surface dock's panel (main_window_surface.cpp).
    [[nodiscard]] SurfacePanel* surfacePanel() const { return m_surfacePanel; }
    /// Create ▸ Subdivision Surface ▸ From Cage File… without the dialog: reads the OBJ
    /// cage at `path` with the panel's scheme, level and mode and starts a surface
    /// session (after asking about unsaved changes). A file that cannot be read is
    /// reported like a failed open (dialog, sceneLoadFailed()); false then.
    bool createSurfaceFromCageFile(const QString& path);
    /// Create ▸ NURBS ▸ From NURBS File… without the dialog: the first surface of the NURBS
    /// JSON file at `path` (docs/nurbs-json.md), tessellated with the panel's density, as a
    /// new surface session (asking about unsaved changes first). Errors are shown as for
    /// other files; false when nothing was created.
    bool createSurfaceFromNurbsFile(const QString& path);
    /// Create ▸ NURBS ▸ Save NURBS Surface As… without the dialog: the NURBS session's
    /// surface at its shown control points, written atomically. False (with a message)
    /// when there is no NURBS session or the file cannot be written.
    bool saveNurbsSurface(const QString& path);

signals:
    /// A scene is shown; `source` as given to openSource().
    void sceneLoaded(const QString& source);
    /// An animation is shown (its rest pose as the scene); `source` as given to
    /// openAnimation().
    void animationLoaded(const QString& source);
    /// Loading `source` (a scene or an animation) failed with `message`; the previous
    /// scene or animation is still shown.
    void sceneLoadFailed(const QString& source, const QString& message);
    /// addObject(`source`) appended its objects to the scene shown.
    void objectAdded(const QString& source);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    MainWindow(std::unique_ptr<QSettings> settings, QWidget* parent);

    void createCentralView();
    void createDock();
    void createStatsDock();
    void createAnimationDocks();
    void createDesignDocks();
    void createSkeletonDock();
    void connectSkeletonParts();
    [[nodiscard]] QString askSkeletonExportPath(const QString& title, const QStringList& filters, const QString& ending);
    void showExportRiggedGltfDialog();
    void showExportSkeletonJsonDialog();
    void createInspectDock();
    void connectInspectParts();
    void showAddObjectDialog();
    void onObjectsLoaded(std::shared_ptr<const LoadedScene> loaded);
    void onObjectTransformChanged();
    void updateSceneEditability();
    void followUndoStacks();
    void createSurfaceDock();
    void createCreateMenu();
    void createControlPointsAction(QMenu* edit, QToolBar* tools);
    void connectSurfaceParts();
    void showSurfaceInPanel();
    void createNurbsPrimitive(NurbsPrimitive primitive);
    void createSubdivisionFromCage(SubdivisionCage cage, const QString& label);
    [[nodiscard]] QString askSurfaceFile(const QString& title, const QString& filter);
    void showCreateFromCageDialog();
    bool createSurfaceSession(const SurfaceDefinition& definition, const QString& name, bool askToSave);
    void rebuildSurface();
    void showCreateFromNurbsDialog();
    void showSaveNurbsDialog();
    void createDesignFileActions(QMenu* file);
    void createEditMenu();
    void connectDesignParts();
    void startDesignSession();
    void onProjectOpened(std::shared_ptr<const timeline::Project> project, const QString& path);
    [[nodiscard]] timeline::ProjectExtras projectExtras() const;
    void createFileMenu();
    void createViewMenu();
    void createHelpMenu();
    void rebuildRecentMenu();
    void rebuildRecentAnimationMenu();
    void connectParts();
    void connectAnimationParts();
    void restoreSettings();
    void saveWindowState();

    void showOpenDialog();
    void showExportDialog();
    void showAbout();
    void openRecent(const QString& path);
    void showOpenAnimationDialog();
    void openRecentAnimation(const QString& path);
    void showExportSegmentationDialog();
    void showExportSkinningDialog();
    void passSegmentationToSkinning();
    void openDefaultIfNothingRequested();
    void onSceneLoaded(std::shared_ptr<const LoadedScene> loaded);
    void onAnimationLoaded(std::shared_ptr<const LoadedAnimation> loaded);
    void showScene(std::shared_ptr<const LoadedScene> loaded, const Bounds& bounds);
    void clearAnimation();
    void showPose(int pose);
    void showSegmentColors();
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
    SceneLoader* m_objectLoader = nullptr; ///< File ▸ Add Object…
    InspectScene* m_inspect = nullptr;
    ScenePanel* m_scenePanel = nullptr;
    QDockWidget* m_sceneDock = nullptr;
    AnimationOpener* m_animationOpener = nullptr;
    TimelinePanel* m_timeline = nullptr;
    QDockWidget* m_timelineDock = nullptr;
    SegmentationPanel* m_segmentation = nullptr;
    QDockWidget* m_segmentationDock = nullptr;
    SkinningPanel* m_skinning = nullptr;
    QDockWidget* m_skinningDock = nullptr;
    SkeletonPanel* m_skeleton = nullptr;
    QDockWidget* m_skeletonDock = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_recentAnimationMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    DesignWorkspace* m_design = nullptr;
    BrushPanel* m_brushPanel = nullptr;
    QDockWidget* m_brushDock = nullptr;
    DeformationTimelinePanel* m_deformationPanel = nullptr;
    QDockWidget* m_deformationDock = nullptr;
    ProjectFiles* m_projectFiles = nullptr;
    SessionRecovery* m_recovery = nullptr;
    HistoryExports* m_exports = nullptr;
    QAction* m_brushAction = nullptr;
    QAction* m_newSetAction = nullptr;
    QAction* m_controlPointsAction = nullptr;
    SurfacePanel* m_surfacePanel = nullptr;
    QDockWidget* m_surfaceDock = nullptr;
    QAction* m_saveNurbsAction = nullptr;
    RecentFiles m_recent;
    RecentFiles m_recentAnimations{QStringLiteral("recentAnimations")};
    std::shared_ptr<const LoadedScene> m_scene;
    std::shared_ptr<const LoadedAnimation> m_animation;
    bool m_openRequested = false;
};

} // namespace trimlab::ui
