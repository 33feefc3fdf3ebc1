// The designer workflow's parts of the main window (main_window.h): the Brush and
// Deformation timeline docks, Edit menu, the project and history entries of the File
// menu, and how a shown mesh or an opened project becomes a DesignSession. Kept apart
// from main_window.cpp so that each file stays about one thing.
#include "main_window.h"

#include "brush_panel.h"
#include "brush_settings_store.h"
#include "brush_tool.h"
#include "deformation_timeline_panel.h"
#include "design_session.h"
#include "design_workspace.h"
#include "history_exports.h"
#include "mesh/mesh_validation.h"
#include "project_files.h"
#include "render_panel.h"
#include "session_recovery.h"
#include "surface/control_edit.h"
#include "surface/surface_scenes.h"
#include "timeline/project_file.h"
#include "viewport_widget.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <QAction>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoGroup>

#include <optional>
#include <string_view>

namespace trimlab::ui {

namespace {

constexpr int kStatusMessageMs = 5000;
const QString kDesignFpsKey = QStringLiteral("design/fps");

/// A surface demo ("demo:nurbs-sphere", …) is edited through its control points: the
/// history of its definition, when its tessellation is exactly the mesh shown (nullopt
/// otherwise, and for every other source: those start a plain mesh history).
std::optional<timeline::Timeline> surfaceDemoHistory(const LoadedScene& scene)
{
    if (!isDemoSource(scene.source) || scene.scene.objects.size() != 1)
        return std::nullopt;
    const std::optional<SurfaceDefinition> definition =
        surfaceDemoDefinition(std::string_view(scene.source).substr(kDemoPrefix.size()));
    if (!definition)
        return std::nullopt;
    try {
        timeline::Timeline history = surfaceTimeline(*definition);
        const TriangleMesh& shown = scene.scene.objects.front().mesh;
        if (history.base().triangles != shown.triangles || history.base().positions != shown.positions)
            return std::nullopt;
        return history;
    } catch (const std::exception&) {
        return std::nullopt; // the demo shows anyway, as a plain mesh
    }
}

/// Bounds of every frame of `history`: the base and every position a frame moved to.
Bounds historyBounds(const timeline::Timeline& history)
{
    Bounds bounds = computeBounds(history.base());
    for (int f = 1; f < history.frameCount(); ++f)
        for (const glm::vec3& p : history.frame(f).after)
            bounds.extend(glm::dvec3(p));
    return bounds;
}

} // namespace

void MainWindow::createDesignDocks()
{
    m_deformationPanel = new DeformationTimelinePanel;
    m_design = new DesignWorkspace(m_viewport, m_deformationPanel, this);
    m_brushPanel = new BrushPanel;
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_brushPanel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_brushDock = new QDockWidget(tr("Brush"), this);
    m_brushDock->setObjectName(QStringLiteral("brushDock"));
    m_brushDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_brushDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_brushDock);
    tabifyDockWidget(m_dock, m_brushDock);
    m_deformationDock = new QDockWidget(tr("Deformation timeline"), this);
    m_deformationDock->setObjectName(QStringLiteral("deformationTimelineDock"));
    m_deformationDock->setAllowedAreas(Qt::BottomDockWidgetArea | Qt::TopDockWidgetArea);
    m_deformationDock->setWidget(m_deformationPanel);
    addDockWidget(Qt::BottomDockWidgetArea, m_deformationDock);
    m_dock->raise();
    m_projectFiles = new ProjectFiles(this, *m_settings, *m_design, [this] { return projectExtras(); });
    m_recovery = new SessionRecovery(this, *m_settings, *m_design, *m_projectFiles, [this] { return projectExtras(); });
    m_exports = new HistoryExports(this, *m_settings, *m_design);
}

void MainWindow::createDesignFileActions(QMenu* file)
{
    QAction* save = file->addAction(tr("&Save Project"), m_projectFiles, &ProjectFiles::save);
    save->setShortcut(QKeySequence::Save);
    QAction* saveAs = file->addAction(tr("Save Project &As…"), m_projectFiles, &ProjectFiles::saveAs);
    saveAs->setShortcut(QKeySequence::SaveAs);
    QMenu* exportMenu = file->addMenu(tr("E&xport"));
    exportMenu->addAction(tr("Frames as &OBJ sequence…"), m_exports, &HistoryExports::showExportObjDialog);
    exportMenu->addAction(tr("Deformation as &glTF (morph targets)…"), m_exports,
                          &HistoryExports::showExportGltfDialog);
    QAction* script = file->addAction(tr("Save Stroke &Script…"), m_exports, &HistoryExports::showSaveScriptDialog);
    QAction* replay = file->addAction(tr("Re&play Stroke Script…"), m_exports, &HistoryExports::showReplayDialog);
    const QList<QAction*> needSession{save, saveAs, exportMenu->menuAction(), script, replay};
    connect(m_design, &DesignWorkspace::sessionChanged, this, [this, needSession] {
        for (QAction* action : needSession)
            action->setEnabled(m_design->session() != nullptr);
    });
    for (QAction* action : needSession)
        action->setEnabled(false);
}

// Single-key shortcuts (B, N) act while the viewport or a design dock has focus, never
// while typing elsewhere (as F does for the viewport).
void MainWindow::createEditMenu()
{
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_design->undoGroup()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_design->undoGroup()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    m_brushAction = edit->addAction(tr("&Brush"));
    m_brushAction->setObjectName(QStringLiteral("brushAction"));
    m_brushAction->setCheckable(true);
    m_brushAction->setShortcut(QKeySequence(Qt::Key_B));
    m_brushAction->setToolTip(tr("Brush (B): left drag on the surface deforms the last frame; Shift: along the "
                                 "normal; Alt+left, right or middle drag move the camera"));
    m_newSetAction = edit->addAction(tr("&New Set"), m_deformationPanel, &DeformationTimelinePanel::requestNewSet);
    m_newSetAction->setObjectName(QStringLiteral("newSetAction"));
    m_newSetAction->setShortcut(QKeySequence(Qt::Key_N));
    for (QAction* action : {m_brushAction, m_newSetAction}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_viewport->addAction(action);
        m_brushDock->addAction(action);
        m_deformationDock->addAction(action);
    }
    QToolBar* tools = addToolBar(tr("Design"));
    tools->setObjectName(QStringLiteral("designToolBar"));
    tools->addAction(m_brushAction);
    tools->addAction(m_newSetAction);
    createControlPointsAction(edit, tools);
    tools->addAction(undo);
    tools->addAction(redo);
}

void MainWindow::connectDesignParts()
{
    connect(m_brushAction, &QAction::toggled, this, [this](bool on) {
        m_design->brushTool()->setEnabled(on);
        BrushChoices choices = m_brushPanel->choices();
        choices.toolEnabled = on;
        saveBrushChoices(*m_settings, choices);
        statusBar()->showMessage(on ? tr("Brush on: drag on the surface to deform it (Alt+drag orbits).")
                                    : tr("Brush off."),
                                 kStatusMessageMs);
    });
    connect(m_brushPanel, &BrushPanel::choicesChanged, this, [this] {
        m_design->setBrushSettings(m_brushPanel->settings());
        BrushChoices choices = m_brushPanel->choices();
        choices.toolEnabled = m_brushAction->isChecked();
        saveBrushChoices(*m_settings, choices);
    });
    connect(m_deformationPanel, &DeformationTimelinePanel::fpsChanged, this, [this](int fps) {
        m_settings->setValue(kDesignFpsKey, fps);
        m_exports->setFps(fps);
    });
    connect(m_design, &DesignWorkspace::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, 2 * kStatusMessageMs); });
    connect(m_exports, &HistoryExports::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
    connect(m_design, &DesignWorkspace::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_design, &DesignWorkspace::sessionChanged, this, [this] {
        const DesignSession* session = m_design->session();
        m_brushPanel->setMeshRadius(session ? session->baseBounds().radius() : 0.0);
        m_design->setBrushSettings(m_brushPanel->settings());
        m_deformationDock->setVisible(session != nullptr);
        updateTitle();
    });
    connect(m_projectFiles, &ProjectFiles::opened, this, &MainWindow::onProjectOpened);
    connect(m_projectFiles, &ProjectFiles::failed, this, &MainWindow::onLoadFailed);
    connect(m_projectFiles, &ProjectFiles::saved, this, [this](const QString& path) {
        m_recent.add(path);
        m_recent.save(*m_settings);
        rebuildRecentMenu();
        updateTitle();
        statusBar()->showMessage(tr("Saved %1").arg(path), kStatusMessageMs);
    });
    connect(m_exports, &HistoryExports::problem, this,
            [this](const QString& title, const QString& text, const QString& details) {
                showMessage(QMessageBox::Warning, title, text, details);
            });
}

// A trimmable scene of one object starts a history on that object; anything else (several
// objects, an open surface) ends the one shown.
void MainWindow::startDesignSession()
{
    const bool designable = m_scene && m_scene->trimmable() && m_scene->scene.objects.size() == 1;
    if (!designable) {
        m_design->endSession();
        return;
    }
    const SceneObject& object = m_scene->scene.objects.front();
    m_design->startSession(surfaceDemoHistory(*m_scene).value_or(timeline::Timeline(object.mesh)),
                           object.modelMatrix, QString());
}

void MainWindow::onProjectOpened(std::shared_ptr<const timeline::Project> project, const QString& path)
{
    clearAnimation();
    m_design->endSession();
    auto loaded = std::make_shared<LoadedScene>();
    const QString name = QFileInfo(path).fileName();
    loaded->scene.objects.push_back({name.toStdString(), project->timeline.base(), glm::dmat4(1.0)});
    loaded->source = path.toStdString();
    loaded->displayName = name.toStdString();
    loaded->reports.push_back(validateMesh(project->timeline.base()));
    if (project->extras.staticRule) {
        RenderChoices choices = m_panel->renderChoices();
        choices.trim.rule = *project->extras.staticRule;
        m_panel->setRenderChoices(choices);
    }
    const Bounds bounds = historyBounds(project->timeline);
    showScene(loaded, bounds); // the session below widens the view bounds to every frame
    m_design->startSession(project->timeline, glm::dmat4(1.0), QFileInfo(path).absoluteFilePath());
    if (const auto& view = project->extras.view)
        m_viewport->setCamera(Camera{view->eye, view->target, view->up, view->fovyDegrees});
    if (m_recovery->adoptRecovered(path)) {
        updateTitle();
        statusBar()->showMessage(tr("Recovered the unsaved deformation history (%1 frames). Save it to keep it.")
                                     .arg(project->timeline.frameCount()),
                                 2 * kStatusMessageMs);
        emit sceneLoaded(path);
        return;
    }
    m_recent.add(path);
    m_recent.save(*m_settings);
    rebuildRecentMenu();
    updateTitle();
    statusBar()->showMessage(tr("%1: %2 frames in %3 sets")
                                 .arg(name)
                                 .arg(project->timeline.frameCount())
                                 .arg(project->timeline.sets().size()),
                             kStatusMessageMs);
    emit sceneLoaded(path);
}

// The camera is stored in the mesh's object space (the project has no model matrix).
timeline::ProjectExtras MainWindow::projectExtras() const
{
    timeline::ProjectExtras extras;
    const DesignSession* session = m_design->session();
    const glm::dmat4 toObject = session ? glm::inverse(session->modelMatrix()) : glm::dmat4(1.0);
    const Camera camera = m_viewport->camera();
    timeline::ProjectView view;
    view.eye = glm::dvec3(toObject * glm::dvec4(camera.eye, 1.0));
    view.target = glm::dvec3(toObject * glm::dvec4(camera.target, 1.0));
    view.up = glm::normalize(glm::dvec3(toObject * glm::dvec4(camera.up, 0.0)));
    view.fovyDegrees = camera.fovyDegrees;
    extras.view = view;
    extras.staticRule = m_panel->renderChoices().trim.rule;
    return extras;
}

} // namespace trimlab::ui
