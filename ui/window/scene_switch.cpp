#include "ui/window/scene_switch.h"

#include "ui/animation/animation_opener.h"
#include "ui/animation/animation_workspace.h"
#include "ui/common/current_document.h"
#include "ui/common/loaded_animation.h"
#include "ui/common/window_context.h"
#include "ui/design/design_workspace.h"
#include "ui/design/history_exports.h"
#include "ui/design/project_files.h"
#include "ui/design/session_recovery.h"
#include "ui/inspect/inspect_scene.h"
#include "ui/inspect/inspect_workspace.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/skeleton/skeleton_panel.h"
#include "ui/skeleton/skeleton_workspace.h"
#include "ui/viewport/viewport_widget.h"
#include "ui/window/recent_files_menu.h"
#include "ui/common/scene_loader.h"

#include "core/animation/mesh_animation.h"
#include "core/catalog/closed_scene.h"
#include "core/catalog/scene_source.h"
#include "core/catalog/surface_scenes.h"
#include "core/mesh/mesh_validation.h"
#include "core/timeline/frame_chain.h"
#include "core/timeline/project_file.h"
#include "core/timeline/view_settings.h"

#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QRegularExpression>
#include <QStatusBar>
#include <QWidget>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace trimlab::ui {

namespace {

QString sceneLabel(const QString& source)
{
    if (isDemoSource(source.toStdString()))
        return source;
    return QFileInfo(source).fileName();
}

/// " — no trimming: REASON" for a scene the trim modes cannot classify, "" otherwise (it
/// said "trim modes unavailable" without the reason).
QString trimUnavailableNote(const LoadedScene& scene)
{
    if (scene.trimmable())
        return {};
    return SceneSwitch::tr(" — no trimming: %1").arg(QString::fromStdString(scene.trimUnavailableReason()));
}

/// A one-object scene of `history`'s base mesh named `name`, opened from `source`.
std::shared_ptr<LoadedScene> historyScene(const timeline::Timeline& history, const QString& name, const QString& source)
{
    auto loaded = std::make_shared<LoadedScene>();
    loaded->scene.objects.push_back({name.toStdString(), history.base(), glm::dmat4(1.0)});
    loaded->source = source.toStdString();
    loaded->displayName = name.toStdString();
    loaded->reports.push_back(validateMesh(history.base()));
    return loaded;
}

/// The view settings a document opened with `extras` (a project's, or none) starts with:
/// the saved ones, else the defaults for a scene of `bounds`.
timeline::DocumentSettings openedSettings(const timeline::ProjectExtras* extras, const Bounds& bounds, bool hasHistory)
{
    timeline::DocumentSettings settings = timeline::documentDefaults(bounds, hasHistory);
    if (!extras)
        return settings;
    const StaticRule rule = extras->staticRule.value_or(settings.trim.rule);
    if (extras->viewSettings)
        return timeline::documentSettings(*extras->viewSettings, rule, bounds);
    settings.trim.rule = rule;
    return settings;
}

} // namespace

SceneSwitch::SceneSwitch(QWidget* window, ViewportWidget* viewport, CurrentDocument& document)
    : QObject(window),
      m_viewport(viewport),
      m_document(document),
      m_loader(new SceneLoader(window)),
      m_animationOpener(new AnimationOpener(window))
{
}

SceneSwitch::~SceneSwitch() = default;

void SceneSwitch::attach(const WindowContext& context, const Features& features, QMenu* recentFiles,
                         QMenu* recentAnimations)
{
    m_context = &context;
    m_features = features;
    m_recent = new RecentFilesMenu(
        recentFiles, context.settings(), QStringLiteral("recentFiles"),
        [this](const QString& path) { openRecent(path); }, this);
    m_recentAnimations = new RecentFilesMenu(
        recentAnimations, context.settings(), QStringLiteral("recentAnimations"),
        [this](const QString& path) { openRecentAnimation(path); }, this);
    connectLoaders();
}

void SceneSwitch::connectLoaders()
{
    const auto canceled = [this](const QString& source) {
        m_context->showStatus(tr("Opening %1 canceled.").arg(sceneLabel(source)));
    };
    connect(m_loader, &SceneLoader::loaded, this, &SceneSwitch::onSceneLoaded);
    connect(m_loader, &SceneLoader::failed, this, &SceneSwitch::reportOpenFailure);
    connect(m_loader, &SceneLoader::canceled, this, canceled);
    connect(m_animationOpener, &AnimationOpener::loaded, this, &SceneSwitch::onAnimationLoaded);
    connect(m_animationOpener, &AnimationOpener::failed, this, &SceneSwitch::reportOpenFailure);
    connect(m_animationOpener, &AnimationOpener::canceled, this, canceled);
    ProjectFiles* projects = m_features.design->projectFiles();
    connect(projects, &ProjectFiles::opened, this, &SceneSwitch::onProjectOpened);
    connect(projects, &ProjectFiles::failed, this, &SceneSwitch::reportOpenFailure);
    connect(projects, &ProjectFiles::saved, this, [this](const QString& path) {
        m_recent->add(path);
        m_context->showStatus(tr("Saved %1").arg(path));
    });
    InspectWorkspace* inspect = m_features.inspect;
    projects->setSceneSource([inspect] {
        const std::shared_ptr<const LoadedScene>& scene = inspect->scene()->scene();
        if (!scene || inspect->showsAnimation())
            return ProjectFiles::ShownScene{};
        return ProjectFiles::ShownScene{scene, inspect->csg()};
    });
    connect(inspect, &InspectWorkspace::transformed, this, &SceneSwitch::onSceneTransformed);
    connect(inspect, &InspectWorkspace::objectsAppended, this, &SceneSwitch::onObjectsAppended);
    connect(inspect, &InspectWorkspace::addFailed, this, &SceneSwitch::sceneLoadFailed);
}

QStringList SceneSwitch::recentFiles() const
{
    return m_recent->paths();
}

QStringList SceneSwitch::recentAnimations() const
{
    return m_recentAnimations->paths();
}

bool SceneSwitch::confirmReplacingShown()
{
    return m_features.design->projectFiles()->maybeSave() && m_features.animation->confirmDiscardSkinningEdits();
}

void SceneSwitch::openSource(const QString& source)
{
    ProjectFiles* projects = m_features.design->projectFiles();
    if (!confirmReplacingShown())
        return;
    m_openRequested = true;
    if (ProjectFiles::isProjectPath(source)) {
        m_loader->cancel();
        m_animationOpener->cancel();
        m_context->showStatus(tr("Opening project %1…").arg(sceneLabel(source)), 0);
        projects->open(source);
        return;
    }
    if (openHistoryDemo(source))
        return;
    m_animationOpener->cancel(); // the newest request wins
    m_features.inspect->objectLoader()->cancel();
    m_context->showStatus(tr("Opening %1…").arg(sceneLabel(source)), 0);
    m_loader->load(source);
}

// A surface demo that carries a deformation history ("demo:subdivision-push") opens like a
// project: its control-point history with its sets, showing the last frame. Loading it as
// a scene would tessellate only that last frame into a plain mesh with nothing to edit.
bool SceneSwitch::openHistoryDemo(const QString& source)
{
    const std::string text = source.toStdString();
    if (!isDemoSource(text))
        return false;
    std::optional<timeline::Timeline> history = surfaceDemoHistory(std::string_view(text).substr(kDemoPrefix.size()));
    if (!history)
        return false;
    m_features.inspect->objectLoader()->cancel();
    const int frames = history->frameCount();
    const int sets = int(history->sets().size());
    showHistory(std::move(*history), source);
    m_context->showStatus(tr("%1: %2 frames in %3 sets").arg(source).arg(frames).arg(sets));
    emit sceneLoaded(source);
    return true;
}

void SceneSwitch::openAnimation(const QString& source)
{
    if (!confirmReplacingShown())
        return;
    m_openRequested = true;
    m_loader->cancel(); // the newest request wins
    m_context->showStatus(tr("Opening animation %1…").arg(sceneLabel(source)), 0);
    m_animationOpener->open(source);
}

bool SceneSwitch::isLoading() const
{
    const DesignWorkspace* design = m_features.design;
    return m_loader->isLoading() || m_features.inspect->objectLoader()->isLoading() || m_animationOpener->isLoading() ||
           design->projectFiles()->isOpening() || design->historyExports()->isReplaying();
}

void SceneSwitch::openRecent(const QString& path)
{
    if (QFileInfo::exists(path)) {
        openSource(path);
        return;
    }
    m_recent->remove(path);
    m_context->showMessage(QMessageBox::Warning, tr("File not found"), tr("“%1” no longer exists.").arg(path),
                           tr("It was removed from the recent files."));
}

void SceneSwitch::openRecentAnimation(const QString& path)
{
    // A pattern (dir/mesh_*.obj, dir/mesh_%04d.obj) is not a file; its folder must exist.
    const QFileInfo info(path);
    const bool pattern = path.contains(QRegularExpression(QStringLiteral("[*?%]")));
    if (info.exists() || (pattern && info.dir().exists())) {
        openAnimation(path);
        return;
    }
    m_recentAnimations->remove(path);
    m_context->showMessage(QMessageBox::Warning, tr("Animation not found"), tr("“%1” no longer exists.").arg(path),
                           tr("It was removed from the recent animations."));
}

void SceneSwitch::reportOpenFailure(const QString& source, const QString& message)
{
    m_context->window().statusBar()->clearMessage();
    m_context->showMessage(QMessageBox::Critical, tr("Could not open"),
                           tr("Could not open “%1”.").arg(sceneLabel(source)), message);
    emit sceneLoadFailed(source, message);
}

void SceneSwitch::cancelPendingLoads()
{
    m_openRequested = true; // the newest request wins, even over the first start's default demo
    if (m_loader->isLoading())
        m_loader->cancel();
    if (m_animationOpener->isLoading())
        m_animationOpener->cancel();
}

void SceneSwitch::onSceneLoaded(std::shared_ptr<const LoadedScene> loaded)
{
    showLoadedScene(std::move(loaded), std::nullopt);
}

void SceneSwitch::showLoadedScene(std::shared_ptr<const LoadedScene> loaded,
                                  const std::optional<timeline::DocumentSettings>& settings)
{
    m_features.animation->clear();
    m_features.design->endSession(); // before the viewport takes the new scene
    const Bounds bounds = loaded->scene.worldBounds();
    const bool designable = loaded->trimmable() && loaded->scene.objects.size() == 1;
    const Document::Kind kind = designable                         ? Document::Kind::Design
                                : loaded->scene.objects.size() > 1 ? Document::Kind::Scene
                                                                   : Document::Kind::Mesh;
    const QString name = QString::fromStdString(loaded->displayName);
    showScene(std::move(loaded), bounds,
              newDocument(kind, name, settings.value_or(openedSettings(nullptr, bounds, false))));
    startDesignSession();
    const QString source = QString::fromStdString(m_scene->source);
    if (!isDemoSource(m_scene->source))
        m_recent->add(source);
    m_context->showStatus(tr("%1: %2 triangles%3")
                              .arg(QString::fromStdString(m_scene->displayName))
                              .arg(m_scene->scene.triangleCount())
                              .arg(trimUnavailableNote(*m_scene)));
    emit sceneLoaded(source);
}

void SceneSwitch::onAnimationLoaded(std::shared_ptr<const LoadedAnimation> loaded)
{
    showLoadedAnimation(std::move(loaded), std::nullopt);
}

void SceneSwitch::showLoadedAnimation(std::shared_ptr<const LoadedAnimation> loaded,
                                      const std::optional<timeline::DocumentSettings>& settings)
{
    m_features.design->endSession(); // an animation's poses are not a deformation history
    showScene(loaded->restScene, loaded->bounds,
              newDocument(Document::Kind::Animation, QString::fromStdString(loaded->restScene->displayName),
                          settings.value_or(openedSettings(nullptr, loaded->bounds, false))),
              true);
    m_features.skeleton->panel()->setScene(nullptr); // the timeline drives the poses of an animation
    m_viewport->setMotionBounds(loaded->bounds);     // Fit frames every pose; none crosses the far plane
    m_features.animation->show(loaded);
    const MeshAnimation& animation = *loaded->animation;
    const QString source = QString::fromStdString(m_scene->source);
    m_recentAnimations->add(source);
    m_context->showStatus(tr("%1: %2 poses, %3 vertices, %4 triangles%5")
                              .arg(QString::fromStdString(m_scene->displayName))
                              .arg(animation.poseCount())
                              .arg(animation.vertexCount())
                              .arg(animation.triangleCount())
                              .arg(trimUnavailableNote(*m_scene)));
    emit animationLoaded(source);
}

bool SceneSwitch::shownHasHoles() const
{
    if (!m_scene)
        return false;
    return std::any_of(m_scene->reports.begin(), m_scene->reports.end(),
                       [](const MeshValidationReport& report) { return report.boundaryEdges.any(); });
}

void SceneSwitch::closeShownHoles()
{
    if (!shownHasHoles() || isLoading() || !confirmReplacingShown())
        return;
    const QString name = QString::fromStdString(m_scene->displayName);
    const std::optional<timeline::DocumentSettings> settings =
        m_document.get() ? std::optional(m_document.get()->settings()) : std::nullopt;
    const std::shared_ptr<const LoadedAnimation> animation = m_features.animation->animation();
    HoleClosing closing;
    try {
        if (animation && m_features.inspect->showsAnimation()) {
            showLoadedAnimation(std::make_shared<const LoadedAnimation>(withHolesClosed(*animation, &closing)),
                                settings);
        } else {
            auto closed = std::make_shared<LoadedScene>(*m_scene);
            closing = closeSceneHoles(*closed);
            showLoadedScene(std::move(closed), settings);
        }
    } catch (const std::exception& e) {
        m_context->showMessage(QMessageBox::Warning, tr("Cannot close the holes"),
                               tr("The holes of “%1” cannot be closed; nothing was changed.").arg(name),
                               QString::fromUtf8(e.what()));
        return;
    }
    m_context->showStatus(
        tr("%1: closed %2%3")
            .arg(name, QString::fromStdString(holeClosingText(closing)), trimUnavailableNote(*m_scene)));
    if (!closing.crossing.empty())
        m_context->showMessage(QMessageBox::Warning, tr("Close Holes"),
                               tr("A fan that closes a hole of “%1” crosses its surface.").arg(name),
                               QString::fromStdString(closing.crossing));
}

void SceneSwitch::onProjectOpened(std::shared_ptr<const timeline::Project> project, const QString& path)
{
    DesignWorkspace* design = m_features.design;
    m_features.animation->clear();
    design->endSession();
    if (project->scene) {
        showSceneProject(*project, path);
        return;
    }
    const QString name = QFileInfo(path).fileName();
    std::shared_ptr<LoadedScene> loaded = historyScene(project->timeline, name, path);
    const timeline::DocumentSettings settings =
        openedSettings(&project->extras, loaded->scene.worldBounds(), project->timeline.frameCount() > 1);
    // The session below widens the view bounds to every frame.
    showScene(std::move(loaded), timeline::historyBounds(project->timeline),
              newDocument(Document::Kind::Design, name, settings, path));
    design->startSession(project->timeline, glm::dmat4(1.0));
    if (const auto& view = project->extras.view)
        m_viewport->setCamera(Camera{view->eye, view->target, view->up, view->fovyDegrees});
    if (adoptIfRecovered(path, project->timeline.frameCount()))
        return;
    m_recent->add(path);
    m_context->showStatus(tr("%1: %2 frames in %3 sets")
                              .arg(name)
                              .arg(project->timeline.frameCount())
                              .arg(project->timeline.sets().size()));
    emit sceneLoaded(path);
}

// An autosaved document being recovered gets its own identity back (session_recovery.h).
bool SceneSwitch::adoptIfRecovered(const QString& path, int frames)
{
    if (!m_features.design->sessionRecovery()->adoptRecovered(path))
        return false;
    m_context->showStatus(tr("Recovered the unsaved work (%1). Save it to keep it.")
                              .arg(frames > 0 ? tr("%n frame(s)", nullptr, frames) : tr("a scene")),
                          2 * kStatusMessageMs);
    emit sceneLoaded(path);
    return true;
}

// A scene project: its objects where they were placed, its CSG and rules (the Scene panel
// starts from them), its camera. It starts no design session, even for one object: the
// project is the scene, and Save Project writes it back as one.
void SceneSwitch::showSceneProject(const timeline::Project& project, const QString& path)
{
    const QString name = QFileInfo(path).fileName();
    auto loaded = std::make_shared<LoadedScene>(
        projectSceneLoaded(*project.scene, project.extras.staticRule, path.toStdString(), name.toStdString()));
    const Bounds bounds = loaded->scene.worldBounds();
    showScene(std::move(loaded), bounds,
              newDocument(Document::Kind::Scene, name, openedSettings(&project.extras, bounds, false), path));
    if (const auto& view = project.extras.view)
        m_viewport->setCamera(Camera{view->eye, view->target, view->up, view->fovyDegrees});
    if (adoptIfRecovered(path, 0))
        return;
    m_recent->add(path);
    m_context->showStatus(tr("%1: a scene of %2 objects%3")
                              .arg(name)
                              .arg(m_scene->scene.objects.size())
                              .arg(trimUnavailableNote(*m_scene)));
    emit sceneLoaded(path);
}

void SceneSwitch::showHistory(timeline::Timeline history, const QString& name)
{
    cancelPendingLoads();
    m_features.animation->clear();
    m_features.design->endSession();
    const Bounds bounds = computeBounds(history.base());
    const timeline::DocumentSettings settings = openedSettings(nullptr, bounds, history.frameCount() > 1);
    showScene(historyScene(history, name, name), bounds, newDocument(Document::Kind::Design, name, settings));
    m_features.design->startSession(std::move(history), glm::dmat4(1.0));
}

// The grown scene stays the same document, now a scene: the history of a design ends
// (the user was asked to save it) and a design project's file no longer holds it; the
// clipping planes keep their place relative to the grown bounds.
void SceneSwitch::onObjectsAppended(const QString& source, const QString& displayName)
{
    Document* document = m_document.get();
    const Bounds before = m_scene->scene.worldBounds();
    if (m_features.design->session()) {
        m_features.design->endSession(); // before the viewport takes the grown scene; several objects are not designed
        document->undoStack()->clear();  // its commands edited the history
        document->setFilePath(QString());
    }
    document->setKind(Document::Kind::Scene);
    const InspectScene* inspect = m_features.inspect->scene();
    m_scene = inspect->scene();
    const Bounds bounds = m_scene->scene.worldBounds();
    document->setSettings(timeline::refitClipPlanes(document->settings(), before, bounds));
    document->markChanged();
    m_features.render->showSceneInfo(bounds, m_scene->trimmable(),
                                     QString::fromStdString(m_scene->trimUnavailableReason()));
    m_viewport->replaceScene(std::shared_ptr<const Scene>(m_scene, &m_scene->scene));
    emit sceneShown();
    const int objects = inspect->objectCount();
    m_context->showStatus(tr("Added %1: the scene has %2 objects%3")
                              .arg(displayName)
                              .arg(objects)
                              .arg(objects > kMaxCsgOperands
                                       ? tr(" (CSG and collisions address objects 0 to %1)").arg(kMaxCsgOperands - 1)
                                       : QString()));
    emit objectAdded(source);
}

// A transform edit (or its undo) replaced the scene by one whose single model matrix
// differs: only the matrices go to the GPU, the camera stays.
void SceneSwitch::onSceneTransformed()
{
    m_scene = m_features.inspect->scene()->scene();
    std::shared_ptr<const Scene> scene(m_scene, &m_scene->scene);
    try {
        m_viewport->setSceneTransforms(scene);
    } catch (const std::invalid_argument&) {
        m_viewport->replaceScene(scene); // the view showed other geometry (never expected): upload it all
    }
    m_features.render->setClipBounds(m_scene->scene.worldBounds());
    emit boundsChanged(); // the cap spacing follows the scene's radius
}

// What a mesh, a history and an animation's rest pose (`animation`) share: a new document
// with its view settings, the scene, the trim controls (with `bounds` for the clip
// offset), the features that work on the shown scene.
void SceneSwitch::showScene(std::shared_ptr<const LoadedScene> loaded, const Bounds& bounds,
                            std::unique_ptr<Document> document, bool animation)
{
    m_scene = std::move(loaded);
    m_document.replace(std::move(document)); // first: the features below use its undo stack
    m_features.render->showSceneInfo(bounds, m_scene->trimmable(),
                                     QString::fromStdString(m_scene->trimUnavailableReason()));
    m_viewport->setScene(std::shared_ptr<const Scene>(m_scene, &m_scene->scene));
    m_features.skeleton->panel()->setScene(m_scene); // after the viewport: its result never meets another mesh
    m_features.inspect->showScene(m_scene, animation);
    emit sceneShown();
}

std::unique_ptr<Document> SceneSwitch::newDocument(Document::Kind kind, const QString& name,
                                                   const timeline::DocumentSettings& settings,
                                                   const QString& filePath) const
{
    return std::make_unique<Document>(kind, name, settings, filePath);
}

// A trimmable scene of one object starts a history on that object (a surface demo's
// through its control points); anything else (several objects, an open surface) ends
// the one shown.
void SceneSwitch::startDesignSession()
{
    const bool designable = m_scene && m_scene->trimmable() && m_scene->scene.objects.size() == 1;
    if (!designable) {
        m_features.design->endSession();
        return;
    }
    const SceneObject& object = m_scene->scene.objects.front();
    m_features.design->startSession(
        surfaceDemoHistory(m_scene->source, object.mesh).value_or(timeline::Timeline(object.mesh)), object.modelMatrix);
}

} // namespace trimlab::ui
