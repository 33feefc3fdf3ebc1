#include "ui/surface/surface_workspace.h"

#include "ui/common/window_context.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/design/control_net_overlay.h"
#include "ui/design/control_point_tool.h"
#include "ui/surface/surface_definitions.h"
#include "ui/surface/surface_panel.h"
#include "ui/surface/surface_settings_store.h"
#include "ui/viewport/viewport_widget.h"

#include "core/surface/cage_obj.h"
#include "core/surface/nurbs_json.h"
#include "core/surface/subdivision_cages.h"
#include "core/timeline/control_edit.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QIcon>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>

namespace trimlab::ui {

namespace {

const QString kCageDirectoryKey = QStringLiteral("surface/lastCageDirectory");

} // namespace

SurfaceWorkspace::SurfaceWorkspace(const WindowContext& context, DesignWorkspace& design, QObject* parent)
    : QObject(parent), m_context(context), m_design(design), m_panel(new SurfacePanel)
{
    m_dock = m_context.addSideDock(tr("Surface"), QStringLiteral("surfaceDock"), m_panel, m_design.brushDock());
    m_panel->setChoices(loadSurfaceChoices(m_context.settings()));
    createControlPointsAction();
    connectParts();
}

void SurfaceWorkspace::addCreateMenu(QMenuBar* menuBar)
{
    QMenu* create = menuBar->addMenu(tr("&Create"));
    create->setObjectName(QStringLiteral("createMenu"));
    QMenu* nurbs = create->addMenu(tr("&NURBS"));
    for (const NurbsPrimitive primitive : nurbsPrimitives()) {
        QAction* action = nurbs->addAction(nurbsPrimitiveLabel(primitive), this,
                                           [this, primitive] { createNurbsPrimitive(primitive); });
        action->setObjectName(QStringLiteral("createNurbs%1Action").arg(nurbsPrimitiveKey(primitive)));
    }
    nurbs->addSeparator();
    QAction* fromNurbsFile =
        nurbs->addAction(tr("From NURBS &File…"), this, &SurfaceWorkspace::showCreateFromNurbsDialog);
    fromNurbsFile->setObjectName(QStringLiteral("createNurbsFromFileAction"));
    m_saveNurbsAction = nurbs->addAction(tr("&Save NURBS Surface As…"), this, &SurfaceWorkspace::showSaveNurbsDialog);
    m_saveNurbsAction->setObjectName(QStringLiteral("saveNurbsAction"));
    m_saveNurbsAction->setToolTip(tr("Writes the edited NURBS surface — the shown frame's control points — as a "
                                     "NURBS JSON file (docs/nurbs-json.md)"));
    QMenu* subdivision = create->addMenu(tr("&Subdivision Surface"));
    for (const std::string& name : builtInCageNames()) {
        const QString key = QString::fromStdString(name);
        QAction* action = subdivision->addAction(builtInCageLabel(key), this, [this, name] {
            createSubdivisionFromCage(builtInCage(name), builtInCageLabel(QString::fromStdString(name)));
        });
        action->setObjectName(QStringLiteral("createSubdivision_%1Action").arg(key));
    }
    subdivision->addSeparator();
    QAction* fromFile =
        subdivision->addAction(tr("From Cage &File…"), this, &SurfaceWorkspace::showCreateFromCageDialog);
    fromFile->setObjectName(QStringLiteral("createSubdivisionFromFileAction"));
    showSurfaceInPanel(); // enables Save NURBS Surface As… for a NURBS session
}

// Edit ▸ Control Points (P) shares the viewport with the brush: at most one tool is on.
void SurfaceWorkspace::createControlPointsAction()
{
    m_controlPointsAction = new QAction(tr("&Control Points"), this);
    m_controlPointsAction->setObjectName(QStringLiteral("controlPointsAction"));
    m_controlPointsAction->setIcon(QIcon(QStringLiteral(":/icons/control-points.svg")));
    m_controlPointsAction->setCheckable(true);
    m_controlPointsAction->setShortcut(QKeySequence(Qt::Key_P));
    m_controlPointsAction->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_controlPointsAction->setToolTip(tr("Control points (P): click picks a point of the control net, Shift+click "
                                         "adds or removes, drag moves the selection (Ctrl: along the normal)"));
    m_design.viewport()->addAction(m_controlPointsAction);
    m_dock->addAction(m_controlPointsAction);
    auto* group = new QActionGroup(this);
    group->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    group->addAction(m_design.brushAction());
    group->addAction(m_controlPointsAction);
}

void SurfaceWorkspace::connectParts()
{
    ControlPointTool* tool = m_design.controlPointTool();
    connect(m_controlPointsAction, &QAction::toggled, this, [this, tool](bool on) {
        tool->setEnabled(on);
        if (on)
            m_context.showStatus(tr("Control points on: click a point of the net, drag to move it (Ctrl: along the "
                                    "normal, Alt+drag orbits)."));
    });
    connect(tool, &ControlPointTool::selectionChanged, m_panel, &SurfacePanel::setSelectionCount);
    connect(m_panel, &SurfacePanel::showNetToggled, m_design.controlNetOverlay(), &ControlNetOverlay::setNetShown);
    connect(m_panel, &SurfacePanel::moveAlongNormalRequested, &m_design, &DesignWorkspace::moveSelectionAlongNormal);
    connect(m_panel, &SurfacePanel::choicesChanged, this,
            [this] { saveSurfaceChoices(m_context.settings(), m_panel->choices()); });
    connect(m_panel, &SurfacePanel::parametersEdited, this, &SurfaceWorkspace::rebuildSurface);
    connect(&m_design, &DesignWorkspace::sessionChanged, this, &SurfaceWorkspace::showSurfaceInPanel);
    m_design.controlNetOverlay()->setNetShown(m_panel->choices().showNet);
    showSurfaceInPanel();
}

QString SurfaceWorkspace::sceneName(const QString& fallback) const
{
    const std::shared_ptr<const LoadedScene> scene = m_context.host().shownScene();
    return scene ? QString::fromStdString(scene->displayName) : fallback;
}

void SurfaceWorkspace::showSurfaceInPanel()
{
    const DesignSession* session = m_design.session();
    const EditableSurface* surface = session ? session->surface() : nullptr;
    if (m_saveNurbsAction)
        m_saveNurbsAction->setEnabled(surface && surface->kind() == SurfaceKind::Nurbs);
    if (!surface) {
        m_panel->setSurface(SurfacePanel::Kind::None, QString(), 0.0);
        m_panel->setSelectionCount(0);
        return;
    }
    m_panel->setChoices(choicesShowing(surface->definition(), m_panel->choices()));
    m_panel->setSurface(panelKind(surface->definition()), describeSurface(*surface, sceneName(QString())),
                        session->baseBounds().radius());
    m_panel->setSelectionCount(int(m_design.controlPointTool()->selection().size()));
}

void SurfaceWorkspace::createNurbsPrimitive(NurbsPrimitive primitive)
{
    createSession(makePrimitiveDefinition(primitive, m_panel->choices()), nurbsPrimitiveLabel(primitive), true);
}

void SurfaceWorkspace::createSubdivisionFromCage(SubdivisionCage cage, const QString& label)
{
    const SurfaceChoices choices = m_panel->choices();
    createSession(subdivisionDefinition(std::move(cage), SubdivisionSettings{choices.level, choices.mode}), label,
                  true);
}

// The surface file chosen in an Open dialog starting in the last folder used for surface
// files (remembered); "" when the user cancels.
QString SurfaceWorkspace::askSurfaceFile(const QString& title, const QString& filter)
{
    QSettings& settings = m_context.settings();
    const QString path =
        QFileDialog::getOpenFileName(&m_context.window(), title, settings.value(kCageDirectoryKey).toString(), filter);
    if (!path.isEmpty())
        settings.setValue(kCageDirectoryKey, QFileInfo(path).absolutePath());
    return path;
}

void SurfaceWorkspace::showCreateFromCageDialog()
{
    const QString path =
        askSurfaceFile(tr("Subdivision Surface from Cage"), tr("OBJ cages (*.obj *.obj.gz);;All files (*)"));
    if (!path.isEmpty())
        createFromCageFile(path);
}

void SurfaceWorkspace::showCreateFromNurbsDialog()
{
    const QString path = askSurfaceFile(tr("Create NURBS Surface from File"),
                                        tr("NURBS files (*.nurbs.json *.nurbs *.json);;All files (*)"));
    if (!path.isEmpty())
        createFromNurbsFile(path);
}

// A file may hold several surfaces (trimlab render shows them all as objects); a design
// history edits one mesh, so the first surface is the one opened for editing.
bool SurfaceWorkspace::createFromNurbsFile(const QString& path)
{
    try {
        std::vector<NurbsSurface> surfaces = loadNurbsJson(path.toStdString());
        const SurfaceChoices choices = m_panel->choices();
        const std::size_t count = surfaces.size();
        const QString name =
            surfaces.front().name.empty() ? QFileInfo(path).fileName() : QString::fromStdString(surfaces.front().name);
        if (!createSession(nurbsDefinition(std::move(surfaces.front()), choices.segmentsU, choices.segmentsV), name,
                           true))
            return false;
        if (count > 1)
            m_context.showStatus(tr("%1 holds %2 surfaces; the first, “%3”, is open for editing.")
                                     .arg(QFileInfo(path).fileName())
                                     .arg(count)
                                     .arg(name));
        return true;
    } catch (const std::exception& e) {
        m_context.host().reportOpenFailure(path, QString::fromStdString(e.what()));
        return false;
    }
}

void SurfaceWorkspace::showSaveNurbsDialog()
{
    QSettings& settings = m_context.settings();
    QString path =
        QFileDialog::getSaveFileName(&m_context.window(), tr("Save NURBS Surface"),
                                     settings.value(kCageDirectoryKey).toString(), tr("NURBS files (*.nurbs.json)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
        path += QStringLiteral(".nurbs.json");
    settings.setValue(kCageDirectoryKey, QFileInfo(path).absolutePath());
    saveNurbsSurface(path);
}

bool SurfaceWorkspace::saveNurbsSurface(const QString& path)
{
    const DesignSession* session = m_design.session();
    const EditableSurface* surface = session ? session->surface() : nullptr;
    if (!surface || surface->kind() != SurfaceKind::Nurbs) {
        m_context.showStatus(tr("Nothing to save: the shown design is not a NURBS surface."));
        return false;
    }
    try {
        NurbsSurface edited = surface->definition().nurbs().surface;
        const std::vector<glm::dvec3>& points = surface->controlPoints();
        for (std::size_t i = 0; i < points.size(); ++i)
            moveControlPoint(edited, i, points[i]);
        saveNurbsJson(path.toStdString(), std::span(&edited, 1));
    } catch (const std::exception& e) {
        m_context.showMessage(QMessageBox::Critical, tr("Could not save the surface"),
                              tr("Could not write %1.").arg(path), QString::fromStdString(e.what()));
        return false;
    }
    m_context.showStatus(tr("Saved the NURBS surface to %1.").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool SurfaceWorkspace::createFromCageFile(const QString& path)
{
    try {
        SubdivisionCage cage = loadCageObj(path.toStdString(), m_panel->choices().scheme);
        const SurfaceChoices choices = m_panel->choices();
        return createSession(subdivisionDefinition(std::move(cage), SubdivisionSettings{choices.level, choices.mode}),
                             QFileInfo(path).fileName(), true);
    } catch (const std::exception& e) {
        m_context.host().reportOpenFailure(path, QString::fromStdString(e.what()));
        return false;
    }
}

// The new history replaces the shown scene and session; its base is the surface's
// tessellation, so the trim rules, the timeline and project files work as for a mesh.
bool SurfaceWorkspace::createSession(const SurfaceDefinition& definition, const QString& name, bool askToSave)
{
    if (askToSave && !m_context.host().confirmReplacingShown())
        return false;
    timeline::Timeline history;
    try {
        history = surfaceTimeline(definition);
    } catch (const std::exception& e) {
        m_context.showMessage(QMessageBox::Critical, tr("Could not create the surface"),
                              tr("Could not create “%1”.").arg(name), QString::fromStdString(e.what()));
        return false;
    }
    const std::size_t triangles = history.base().triangles.size();
    m_context.host().showHistory(std::move(history), name);
    m_dock->show();
    m_dock->raise();
    m_controlPointsAction->setChecked(true);
    m_context.showStatus(
        tr("%1: %2 control points, %3 triangles").arg(name).arg(definition.controlPointCount()).arg(triangles));
    return true;
}

// Density, level, scheme and mode change the mesh's connectivity, which all frames of a
// history share: the surface is rebuilt from the current control points as a new
// history. Without edits nothing is lost; with edits the user is asked first.
void SurfaceWorkspace::rebuildSurface()
{
    DesignSession* session = m_design.session();
    const EditableSurface* surface = session ? session->surface() : nullptr;
    if (!surface)
        return;
    std::optional<SurfaceDefinition> rebuilt;
    QString problem;
    try {
        rebuilt =
            rebuiltDefinition(surface->definition(), session->timeline().currentControlPoints(), m_panel->choices());
    } catch (const std::exception& e) {
        problem = QString::fromStdString(e.what());
    }
    if (!rebuilt || !problem.isEmpty()) {
        m_context.showStatus(tr("Cannot rebuild the surface: %1").arg(problem), 2 * kStatusMessageMs);
        showSurfaceInPanel(); // the panel shows the surface's parameters again
        return;
    }
    if (*rebuilt == surface->definition())
        return;
    const int edits = session->lastFrame();
    if (edits > 0) {
        const auto answer = QMessageBox::question(
            &m_context.window(), tr("Rebuild the surface"),
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
    const QString name = sceneName(QStringLiteral("surface"));
    ViewportWidget* viewport = m_design.viewport();
    const Camera camera = viewport->camera(); // a rebuild keeps the view
    if (!createSession(*rebuilt, name, false)) {
        showSurfaceInPanel();
        return;
    }
    viewport->setCamera(camera);
}

} // namespace trimlab::ui
