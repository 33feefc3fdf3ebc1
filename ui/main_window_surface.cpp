// The editable-surface parts of the main window (main_window.h; thesis 8.2): the Create
// menu (NURBS primitives, subdivision surfaces from built-in cages or an OBJ cage file),
// the Surface dock, Edit ▸ Control Points (P), and how a created surface becomes a design
// session whose base mesh is its tessellation. Kept apart from main_window_design.cpp so
// that each file stays about one thing.
#include "main_window.h"

#include "brush_tool.h"
#include "control_net_overlay.h"
#include "control_point_tool.h"
#include "design_session.h"
#include "animation_opener.h"
#include "design_workspace.h"
#include "project_files.h"
#include "scene_loader.h"
#include "surface_definitions.h"
#include "surface_panel.h"
#include "surface_settings_store.h"
#include "viewport_widget.h"

#include "mesh/mesh_validation.h"
#include "surface/cage_obj.h"
#include "surface/nurbs_json.h"
#include "surface/control_edit.h"
#include "surface/subdivision_cages.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

namespace trimlab::ui {

namespace {

constexpr int kStatusMessageMs = 5000;
const QString kCageDirectoryKey = QStringLiteral("surface/lastCageDirectory");

} // namespace

void MainWindow::createSurfaceDock()
{
    m_surfacePanel = new SurfacePanel;
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_surfacePanel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_surfaceDock = new QDockWidget(tr("Surface"), this);
    m_surfaceDock->setObjectName(QStringLiteral("surfaceDock"));
    m_surfaceDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    m_surfaceDock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, m_surfaceDock);
    tabifyDockWidget(m_brushDock, m_surfaceDock);
    m_dock->raise();
    m_surfacePanel->setChoices(loadSurfaceChoices(*m_settings));
}

void MainWindow::createCreateMenu()
{
    QMenu* create = menuBar()->addMenu(tr("&Create"));
    create->setObjectName(QStringLiteral("createMenu"));
    QMenu* nurbs = create->addMenu(tr("&NURBS"));
    for (const NurbsPrimitive primitive : nurbsPrimitives()) {
        QAction* action = nurbs->addAction(nurbsPrimitiveLabel(primitive), this,
                                           [this, primitive] { createNurbsPrimitive(primitive); });
        action->setObjectName(QStringLiteral("createNurbs%1Action").arg(nurbsPrimitiveKey(primitive)));
    }
    nurbs->addSeparator();
    QAction* fromNurbsFile = nurbs->addAction(tr("From NURBS &File…"), this, &MainWindow::showCreateFromNurbsDialog);
    fromNurbsFile->setObjectName(QStringLiteral("createNurbsFromFileAction"));
    m_saveNurbsAction = nurbs->addAction(tr("&Save NURBS Surface As…"), this, &MainWindow::showSaveNurbsDialog);
    m_saveNurbsAction->setObjectName(QStringLiteral("saveNurbsAction"));
    m_saveNurbsAction->setToolTip(tr("Writes the edited NURBS surface — the shown frame's control points — as a "
                                     "NURBS JSON file (docs/nurbs-json.md)"));
    m_saveNurbsAction->setEnabled(false);
    QMenu* subdivision = create->addMenu(tr("&Subdivision Surface"));
    for (const std::string& name : builtInCageNames()) {
        const QString key = QString::fromStdString(name);
        QAction* action = subdivision->addAction(builtInCageLabel(key), this, [this, name] {
            createSubdivisionFromCage(builtInCage(name), builtInCageLabel(QString::fromStdString(name)));
        });
        action->setObjectName(QStringLiteral("createSubdivision_%1Action").arg(key));
    }
    subdivision->addSeparator();
    QAction* fromFile = subdivision->addAction(tr("From Cage &File…"), this, &MainWindow::showCreateFromCageDialog);
    fromFile->setObjectName(QStringLiteral("createSubdivisionFromFileAction"));
}

// Edit ▸ Control Points (P) shares the viewport with the brush: at most one tool is on.
void MainWindow::createControlPointsAction(QMenu* edit, QToolBar* tools)
{
    m_controlPointsAction = edit->addAction(tr("&Control Points"));
    m_controlPointsAction->setObjectName(QStringLiteral("controlPointsAction"));
    m_controlPointsAction->setCheckable(true);
    m_controlPointsAction->setShortcut(QKeySequence(Qt::Key_P));
    m_controlPointsAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_controlPointsAction->setToolTip(tr("Control points (P): click picks a point of the control net, Shift+click "
                                         "adds or removes, drag moves the selection (Ctrl: along the normal)"));
    m_viewport->addAction(m_controlPointsAction);
    m_surfaceDock->addAction(m_controlPointsAction);
    tools->addAction(m_controlPointsAction);
    auto* group = new QActionGroup(this);
    group->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    group->addAction(m_brushAction);
    group->addAction(m_controlPointsAction);
}

void MainWindow::connectSurfaceParts()
{
    ControlPointTool* tool = m_design->controlPointTool();
    connect(m_controlPointsAction, &QAction::toggled, this, [this, tool](bool on) {
        tool->setEnabled(on);
        if (on)
            statusBar()->showMessage(tr("Control points on: click a point of the net, drag to move it (Ctrl: "
                                        "along the normal, Alt+drag orbits)."),
                                     kStatusMessageMs);
    });
    connect(tool, &ControlPointTool::selectionChanged, m_surfacePanel, &SurfacePanel::setSelectionCount);
    connect(m_surfacePanel, &SurfacePanel::showNetToggled, m_design->controlNetOverlay(),
            &ControlNetOverlay::setNetShown);
    connect(m_surfacePanel, &SurfacePanel::moveAlongNormalRequested, m_design,
            &DesignWorkspace::moveSelectionAlongNormal);
    connect(m_surfacePanel, &SurfacePanel::choicesChanged, this,
            [this] { saveSurfaceChoices(*m_settings, m_surfacePanel->choices()); });
    connect(m_surfacePanel, &SurfacePanel::parametersEdited, this, &MainWindow::rebuildSurface);
    connect(m_design, &DesignWorkspace::sessionChanged, this, &MainWindow::showSurfaceInPanel);
    m_design->controlNetOverlay()->setNetShown(m_surfacePanel->choices().showNet);
    showSurfaceInPanel();
}

void MainWindow::showSurfaceInPanel()
{
    const DesignSession* session = m_design->session();
    const EditableSurface* surface = session ? session->surface() : nullptr;
    m_saveNurbsAction->setEnabled(surface && surface->kind() == SurfaceKind::Nurbs);
    if (!surface) {
        m_surfacePanel->setSurface(SurfacePanel::Kind::None, QString(), 0.0);
        m_surfacePanel->setSelectionCount(0);
        return;
    }
    m_surfacePanel->setChoices(choicesShowing(surface->definition(), m_surfacePanel->choices()));
    m_surfacePanel->setSurface(panelKind(surface->definition()),
                               describeSurface(*surface, QString::fromStdString(m_scene ? m_scene->displayName : "")),
                               session->baseBounds().radius());
    m_surfacePanel->setSelectionCount(int(m_design->controlPointTool()->selection().size()));
}

void MainWindow::createNurbsPrimitive(NurbsPrimitive primitive)
{
    const SurfaceChoices choices = m_surfacePanel->choices();
    createSurfaceSession(makePrimitiveDefinition(primitive, choices), nurbsPrimitiveLabel(primitive), true);
}

void MainWindow::createSubdivisionFromCage(SubdivisionCage cage, const QString& label)
{
    const SurfaceChoices choices = m_surfacePanel->choices();
    createSurfaceSession(subdivisionDefinition(std::move(cage), SubdivisionSettings{choices.level, choices.mode}),
                         label, true);
}

// The surface file chosen in an Open dialog starting in the last folder used for surface
// files (remembered); "" when the user cancels.
QString MainWindow::askSurfaceFile(const QString& title, const QString& filter)
{
    const QString path =
        QFileDialog::getOpenFileName(this, title, m_settings->value(kCageDirectoryKey).toString(), filter);
    if (!path.isEmpty())
        m_settings->setValue(kCageDirectoryKey, QFileInfo(path).absolutePath());
    return path;
}

void MainWindow::showCreateFromCageDialog()
{
    const QString path =
        askSurfaceFile(tr("Subdivision Surface from Cage"), tr("OBJ cages (*.obj *.obj.gz);;All files (*)"));
    if (!path.isEmpty())
        createSurfaceFromCageFile(path);
}

void MainWindow::showCreateFromNurbsDialog()
{
    const QString path = askSurfaceFile(tr("Create NURBS Surface from File"),
                                        tr("NURBS files (*.nurbs.json *.nurbs *.json);;All files (*)"));
    if (!path.isEmpty())
        createSurfaceFromNurbsFile(path);
}

// A file may hold several surfaces (trimlab render shows them all as objects); a design
// history edits one mesh, so the first surface is the one opened for editing.
bool MainWindow::createSurfaceFromNurbsFile(const QString& path)
{
    try {
        std::vector<NurbsSurface> surfaces = loadNurbsJson(path.toStdString());
        const SurfaceChoices choices = m_surfacePanel->choices();
        const std::size_t count = surfaces.size();
        const QString name = surfaces.front().name.empty() ? QFileInfo(path).fileName()
                                                           : QString::fromStdString(surfaces.front().name);
        if (!createSurfaceSession(nurbsDefinition(std::move(surfaces.front()), choices.segmentsU, choices.segmentsV),
                                  name, true))
            return false;
        if (count > 1)
            statusBar()->showMessage(tr("%1 holds %2 surfaces; the first, “%3”, is open for editing.")
                                         .arg(QFileInfo(path).fileName())
                                         .arg(count)
                                         .arg(name),
                                     kStatusMessageMs);
        return true;
    } catch (const std::exception& e) {
        onLoadFailed(path, QString::fromStdString(e.what()));
        return false;
    }
}

void MainWindow::showSaveNurbsDialog()
{
    QString path = QFileDialog::getSaveFileName(this, tr("Save NURBS Surface"),
                                                m_settings->value(kCageDirectoryKey).toString(),
                                                tr("NURBS files (*.nurbs.json)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
        path += QStringLiteral(".nurbs.json");
    m_settings->setValue(kCageDirectoryKey, QFileInfo(path).absolutePath());
    saveNurbsSurface(path);
}

bool MainWindow::saveNurbsSurface(const QString& path)
{
    const DesignSession* session = m_design->session();
    const EditableSurface* surface = session ? session->surface() : nullptr;
    if (!surface || surface->kind() != SurfaceKind::Nurbs) {
        statusBar()->showMessage(tr("Nothing to save: the shown design is not a NURBS surface."), kStatusMessageMs);
        return false;
    }
    try {
        NurbsSurface edited = surface->definition().nurbs().surface;
        const std::vector<glm::dvec3>& points = surface->controlPoints();
        for (std::size_t i = 0; i < points.size(); ++i)
            moveControlPoint(edited, i, points[i]);
        saveNurbsJson(path.toStdString(), std::span(&edited, 1));
    } catch (const std::exception& e) {
        showMessage(QMessageBox::Critical, tr("Could not save the surface"), tr("Could not write %1.").arg(path),
                    QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(tr("Saved the NURBS surface to %1.").arg(QDir::toNativeSeparators(path)),
                             kStatusMessageMs);
    return true;
}

bool MainWindow::createSurfaceFromCageFile(const QString& path)
{
    try {
        SubdivisionCage cage = loadCageObj(path.toStdString(), m_surfacePanel->choices().scheme);
        const SurfaceChoices choices = m_surfacePanel->choices();
        return createSurfaceSession(subdivisionDefinition(std::move(cage),
                                                          SubdivisionSettings{choices.level, choices.mode}),
                                    QFileInfo(path).fileName(), true);
    } catch (const std::exception& e) {
        onLoadFailed(path, QString::fromStdString(e.what()));
        return false;
    }
}

// The new history replaces the shown scene and session; its base is the surface's
// tessellation, so the trim rules, the timeline and project files work as for a mesh.
bool MainWindow::createSurfaceSession(const SurfaceDefinition& definition, const QString& name, bool askToSave)
{
    if (askToSave && !m_projectFiles->maybeSave())
        return false;
    timeline::Timeline history;
    try {
        history = surfaceTimeline(definition);
    } catch (const std::exception& e) {
        showMessage(QMessageBox::Critical, tr("Could not create the surface"),
                    tr("Could not create “%1”.").arg(name), QString::fromStdString(e.what()));
        return false;
    }
    // The newest request wins: a scene still loading (the first start's default demo)
    // must not replace the surface when it arrives.
    m_openRequested = true;
    if (m_loader->isLoading())
        m_loader->cancel();
    if (m_animationOpener->isLoading())
        m_animationOpener->cancel();
    clearAnimation();
    m_design->endSession();
    auto loaded = std::make_shared<LoadedScene>();
    loaded->scene.objects.push_back({name.toStdString(), history.base(), glm::dmat4(1.0)});
    loaded->source = name.toStdString();
    loaded->displayName = name.toStdString();
    loaded->reports.push_back(validateMesh(history.base()));
    const Bounds bounds = computeBounds(history.base());
    showScene(loaded, bounds);
    const std::size_t triangles = history.base().triangles.size();
    m_design->startSession(std::move(history), glm::dmat4(1.0), QString());
    m_surfaceDock->show();
    m_surfaceDock->raise();
    m_controlPointsAction->setChecked(true);
    updateTitle();
    statusBar()->showMessage(tr("%1: %2 control points, %3 triangles")
                                 .arg(name)
                                 .arg(definition.controlPointCount())
                                 .arg(triangles),
                             kStatusMessageMs);
    return true;
}

// Density, level, scheme and mode change the mesh's connectivity, which all frames of a
// history share: the surface is rebuilt from the current control points as a new
// history. Without edits nothing is lost; with edits the user is asked first.
void MainWindow::rebuildSurface()
{
    DesignSession* session = m_design->session();
    const EditableSurface* surface = session ? session->surface() : nullptr;
    if (!surface)
        return;
    const SurfaceChoices choices = m_surfacePanel->choices();
    std::optional<SurfaceDefinition> rebuilt;
    QString problem;
    try {
        rebuilt = rebuiltDefinition(surface->definition(), session->timeline().currentControlPoints(), choices);
    } catch (const std::exception& e) {
        problem = QString::fromStdString(e.what());
    }
    if (!rebuilt || !problem.isEmpty()) {
        statusBar()->showMessage(tr("Cannot rebuild the surface: %1").arg(problem), 2 * kStatusMessageMs);
        showSurfaceInPanel(); // the panel shows the surface's parameters again
        return;
    }
    if (*rebuilt == surface->definition())
        return;
    const int edits = session->lastFrame();
    if (edits > 0) {
        const auto answer = QMessageBox::question(
            this, tr("Rebuild the surface"),
            tr("These parameters change the mesh's connectivity, which every frame of a history shares. The surface "
               "is rebuilt from the control points of the last frame and starts a new history; the %n edit(s) of "
               "this history cannot be undone afterwards. Save the project first to keep them.",
               nullptr, edits),
            QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Ok) {
            showSurfaceInPanel();
            return;
        }
    }
    const QString name = QString::fromStdString(m_scene ? m_scene->displayName : "surface");
    const Camera camera = m_viewport->camera(); // a rebuild keeps the view
    if (!createSurfaceSession(*rebuilt, name, false)) {
        showSurfaceInPanel();
        return;
    }
    m_viewport->setCamera(camera);
}

} // namespace trimlab::ui
