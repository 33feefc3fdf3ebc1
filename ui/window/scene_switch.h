#pragma once
/// \file
/// The one thing the main window shows — a scene (a mesh, a demo, a NURBS file), a
/// project's design history, a created surface's history, or an animation's rest pose —
/// and how each way of opening something replaces it (SceneHost). Each is a new document
/// (ui/common/document.h) with the file's view settings or the defaults for its bounds,
/// never the settings of the document before; adding objects keeps the document, which
/// becomes a scene. Scenes load off the UI
/// thread (SceneLoader), animations too (AnimationOpener), projects through the design
/// feature's ProjectFiles; the newest request wins and cancels pending ones. Replacing
/// what is shown ends the animation and the design session first, then hands the new
/// scene to the viewport and every feature (sceneShown()), and starts a design session
/// on a trimmable single-object scene. The recent files and recent animations are kept
/// here, as they record what was opened.
///
/// Built in two steps: the window creates it before its feature workspaces (which reach
/// it as their SceneHost), then attach()es them.

#include "ui/common/document.h"
#include "ui/common/scene_host.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

namespace trimlab::timeline {
struct Project;
}

class QMenu;
class QWidget;

namespace trimlab::ui {

class AnimationOpener;
class AnimationWorkspace;
class CurrentDocument;
class DesignWorkspace;
class InspectWorkspace;
class RecentFilesMenu;
class RenderWorkspace;
class SceneLoader;
class SkeletonWorkspace;
class ViewportWidget;
class WindowContext;
struct LoadedAnimation;

class SceneSwitch : public QObject, public SceneHost {
    Q_OBJECT
public:
    /// The features a new scene is handed to.
    struct Features {
        RenderWorkspace* render;
        AnimationWorkspace* animation;
        DesignWorkspace* design;
        SkeletonWorkspace* skeleton;
        InspectWorkspace* inspect;
    };

    /// `window` parents the loaders' progress dialogs and this object; `document` is the
    /// holder of the document shown, which this object replaces.
    SceneSwitch(QWidget* window, ViewportWidget* viewport, CurrentDocument& document);
    ~SceneSwitch() override;
    /// The second step: the window's context, its features, and the File menu's recent
    /// submenus to fill.
    void attach(const WindowContext& context, const Features& features, QMenu* recentFiles, QMenu* recentAnimations);

    /// MainWindow::openSource, openAnimation, isLoading (see there).
    void openSource(const QString& source);
    void openAnimation(const QString& source);
    [[nodiscard]] bool isLoading() const;
    /// Edit ▸ Close Holes: whether the shown mesh, scene or animation has boundary edges.
    [[nodiscard]] bool shownHasHoles() const;
    /// Shows the mesh or animation shown with its holes closed (core/trim/hole_closing.h)
    /// as a new document with the same view settings, which the trim modes can classify
    /// where the holes were the only defect; says what was closed in the status bar, and in
    /// a warning where a fan crosses the surface. A boundary that cannot be closed (it
    /// forms no loops) is reported in a message, and what is shown stays. Asks to save
    /// unsaved work first, like opening.
    void closeShownHoles();
    /// Whether anything was asked to open yet (the first start opens the default demo
    /// only when nothing was).
    [[nodiscard]] bool openRequested() const { return m_openRequested; }

    [[nodiscard]] SceneLoader* sceneLoader() const { return m_loader; }
    [[nodiscard]] AnimationOpener* animationOpener() const { return m_animationOpener; }
    [[nodiscard]] QStringList recentFiles() const;
    [[nodiscard]] QStringList recentAnimations() const;

    // SceneHost
    [[nodiscard]] std::shared_ptr<const LoadedScene> shownScene() const override { return m_scene; }
    void showHistory(timeline::Timeline history, const QString& name) override;
    [[nodiscard]] bool confirmReplacingShown() override;
    void reportOpenFailure(const QString& source, const QString& message) override;

signals:
    /// A new scene is shown (the features have it): the window applies the render
    /// choices.
    void sceneShown();
    /// The shown scene's bounds changed (an object moved or was scaled): the cap spacing
    /// follows them.
    void boundsChanged();
    /// See MainWindow's signals of the same names.
    void sceneLoaded(const QString& source);
    void animationLoaded(const QString& source);
    void sceneLoadFailed(const QString& source, const QString& message);
    void objectAdded(const QString& source);

private:
    void connectLoaders();
    void openRecent(const QString& path);
    void openRecentAnimation(const QString& path);
    void cancelPendingLoads();
    [[nodiscard]] bool openHistoryDemo(const QString& source);
    void onSceneLoaded(std::shared_ptr<const LoadedScene> loaded);
    void onAnimationLoaded(std::shared_ptr<const LoadedAnimation> loaded);
    /// What onSceneLoaded and onAnimationLoaded do, the new document's view settings
    /// `settings` (nullopt: the defaults for the bounds).
    void showLoadedScene(std::shared_ptr<const LoadedScene> loaded,
                         const std::optional<timeline::DocumentSettings>& settings);
    void showLoadedAnimation(std::shared_ptr<const LoadedAnimation> loaded,
                             const std::optional<timeline::DocumentSettings>& settings);
    void onProjectOpened(std::shared_ptr<const timeline::Project> project, const QString& path);
    void onObjectsAppended(const QString& source, const QString& displayName);
    void showSceneProject(const timeline::Project& project, const QString& path);
    [[nodiscard]] bool adoptIfRecovered(const QString& path, int frames);
    void onSceneTransformed();
    void showScene(std::shared_ptr<const LoadedScene> loaded, const Bounds& bounds, std::unique_ptr<Document> document,
                   bool animation = false);
    [[nodiscard]] std::unique_ptr<Document> newDocument(Document::Kind kind, const QString& name,
                                                        const timeline::DocumentSettings& settings,
                                                        const QString& filePath = {}) const;
    void startDesignSession();

    ViewportWidget* m_viewport;
    CurrentDocument& m_document;
    SceneLoader* m_loader;
    AnimationOpener* m_animationOpener;
    const WindowContext* m_context = nullptr;
    Features m_features{};
    RecentFilesMenu* m_recent = nullptr;
    RecentFilesMenu* m_recentAnimations = nullptr;
    std::shared_ptr<const LoadedScene> m_scene;
    bool m_openRequested = false;
};

} // namespace trimlab::ui
