#include "ui/design/design_workspace.h"

#include "ui/common/count_text.h"
#include "ui/common/current_document.h"
#include "ui/common/window_context.h"
#include "ui/design/append_frame_command.h"
#include "ui/design/brush_panel.h"
#include "ui/design/brush_settings_store.h"
#include "ui/design/brush_tool.h"
#include "ui/design/deformation_timeline_panel.h"
#include "ui/design/design_session.h"
#include "ui/design/history_exports.h"
#include "ui/design/project_files.h"
#include "ui/design/session_recovery.h"
#include "ui/design/set_rule_command.h"
#include "ui/design/start_set_command.h"
#include "ui/design/trimmed_region_guard.h"
#include "ui/design/control_net_overlay.h"
#include "ui/design/control_point_tool.h"
#include "ui/viewport/viewport_widget.h"

#include "core/design/control_brush.h"
#include "core/design/session_chain.h"
#include "core/timeline/view_settings.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <QAction>
#include <QDockWidget>
#include <QIcon>
#include <QMainWindow>
#include <QMenu>
#include <QSettings>
#include <QUndoGroup>
#include <QUndoStack>

namespace trimlab::ui {

namespace {

const QString kDesignFpsKey = QStringLiteral("design/fps");

} // namespace

DesignWorkspace::DesignWorkspace(const WindowContext& context, ViewportWidget* viewport, QDockWidget* tabWith,
                                 QObject* parent)
    : QObject(parent),
      m_context(context),
      m_viewport(viewport),
      m_undoGroup(new QUndoGroup(this)),
      m_brush(new BrushTool(viewport, this)),
      m_overlay(new ControlNetOverlay(viewport)),
      m_points(new ControlPointTool(viewport, m_overlay, this)),
      m_shown(viewport->content(), render::ContentOwner::DesignHistory),
      m_poseWatch(viewport->content()->subscribe([this](render::ShownLayer layer) {
          if (layer == render::ShownLayer::Pose)
              onShownPoseChanged();
      })),
      m_guard(std::make_unique<TrimmedRegionGuard>())
{
    createDocks(tabWith);
    createActions();
    createFileParts();
    connectParts();
    // Edit ▸ Undo and Redo act on the document shown.
    connect(&m_context.document(), &CurrentDocument::replaced, this, [this] {
        if (Document* document = m_context.document().get()) {
            m_undoGroup->addStack(document->undoStack());
            m_undoGroup->setActiveStack(document->undoStack());
        }
    });
}

DesignWorkspace::~DesignWorkspace()
{
    m_brush->setSession(nullptr);
    m_points->setSession(nullptr);
}

void DesignWorkspace::createDocks(QDockWidget* tabWith)
{
    m_brushPanel = new BrushPanel;
    m_brushDock = m_context.addSideDock(tr("Brush"), QStringLiteral("brushDock"), m_brushPanel, tabWith);
    m_timelinePanel = new DeformationTimelinePanel;
    m_timelineDock =
        m_context.addBottomDock(tr("Deformation timeline"), QStringLiteral("deformationTimelineDock"), m_timelinePanel);
}

// Single-key shortcuts (B, N) act while the viewport or a design dock has focus, never
// while typing elsewhere (as F does for the viewport).
void DesignWorkspace::createActions()
{
    m_undoAction = m_undoGroup->createUndoAction(&m_context.window(), tr("&Undo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setIcon(QIcon(QStringLiteral(":/icons/undo.svg")));
    m_redoAction = m_undoGroup->createRedoAction(&m_context.window(), tr("&Redo"));
    m_redoAction->setShortcut(QKeySequence::Redo);
    m_redoAction->setIcon(QIcon(QStringLiteral(":/icons/redo.svg")));
    m_brushAction = new QAction(tr("&Brush"), this);
    m_brushAction->setObjectName(QStringLiteral("brushAction"));
    m_brushAction->setIcon(QIcon(QStringLiteral(":/icons/brush.svg")));
    m_brushAction->setCheckable(true);
    m_brushAction->setShortcut(QKeySequence(Qt::Key_B));
    m_brushAction->setToolTip(tr("Brush (B): left drag on the surface deforms the last frame; Shift: along the "
                                 "normal; Alt+left, right or middle drag move the camera"));
    m_newSetAction = new QAction(tr("&New Set"), this);
    m_newSetAction->setObjectName(QStringLiteral("newSetAction"));
    m_newSetAction->setIcon(QIcon(QStringLiteral(":/icons/new-set.svg")));
    m_newSetAction->setShortcut(QKeySequence(Qt::Key_N));
    connect(m_newSetAction, &QAction::triggered, m_timelinePanel, &DeformationTimelinePanel::requestNewSet);
    for (QAction* action : {m_brushAction, m_newSetAction}) {
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        m_viewport->addAction(action);
        m_brushDock->addAction(action);
        m_timelineDock->addAction(action);
    }
}

void DesignWorkspace::createFileParts()
{
    QSettings& settings = m_context.settings();
    m_projectFiles = new ProjectFiles(&m_context.window(), settings, *this, [this] { return projectExtras(); });
    m_recovery = new SessionRecovery(&m_context.window(), settings, *this, *m_projectFiles);
    m_exports = new HistoryExports(&m_context.window(), settings, *this);
}

void DesignWorkspace::addFileActions(QMenu* file)
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
    const QList<QAction*> needSession{exportMenu->menuAction(), script, replay};
    // Save Project saves the history, or without one the scene shown (a scene project).
    const auto refresh = [this, needSession, save, saveAs] {
        for (QAction* action : needSession)
            action->setEnabled(m_session != nullptr);
        for (QAction* action : {save, saveAs})
            action->setEnabled(m_projectFiles->canSave());
    };
    connect(this, &DesignWorkspace::sessionChanged, this, refresh);
    connect(m_projectFiles, &ProjectFiles::saveableChanged, this, refresh);
    refresh();
}

void DesignWorkspace::connectParts()
{
    m_brush->setGuard([this](const BrushDrag& drag) { return m_guard->refuseDrag(*m_session, m_baseRule, drag); });
    const auto controlGuard = [this](const timeline::Frame& frame) {
        return m_guard->refuseControlEdit(*m_session, m_baseRule, frame);
    };
    m_points->setGuard(controlGuard);
    m_brush->setControlGuard(controlGuard);
    connect(m_brush, &BrushTool::statusMessage, this, &DesignWorkspace::statusMessage);
    connect(m_points, &ControlPointTool::statusMessage, this, &DesignWorkspace::statusMessage);
    m_points->setViewRestorer([this] { refreshView(); });
    connect(m_timelinePanel, &DeformationTimelinePanel::frameChosen, this, &DesignWorkspace::showFrame);
    connect(m_timelinePanel, &DeformationTimelinePanel::newSetRequested, this, &DesignWorkspace::startNewSet);
    connect(m_timelinePanel, &DeformationTimelinePanel::ruleChosen, this, &DesignWorkspace::chooseRule);
    connect(m_brushAction, &QAction::toggled, this, [this](bool on) {
        m_brush->setEnabled(on);
        BrushChoices choices = m_brushPanel->choices();
        choices.toolEnabled = on;
        saveBrushChoices(m_context.settings(), choices);
        m_context.showStatus(on ? tr("Brush on: drag on the surface to deform it (Alt+drag orbits).")
                                : tr("Brush off."));
    });
    connect(m_brushPanel, &BrushPanel::choicesChanged, this, [this] {
        setBrushSettings(m_brushPanel->settings());
        BrushChoices choices = m_brushPanel->choices();
        choices.toolEnabled = m_brushAction->isChecked();
        saveBrushChoices(m_context.settings(), choices);
    });
    connect(m_timelinePanel, &DeformationTimelinePanel::fpsChanged, this, [this](int fps) {
        m_context.settings().setValue(kDesignFpsKey, fps);
        m_exports->setFps(fps);
    });
    connect(this, &DesignWorkspace::statusMessage, this,
            [this](const QString& message) { m_context.showStatus(message, 2 * kStatusMessageMs); });
    connect(m_exports, &HistoryExports::statusMessage, this,
            [this](const QString& message) { m_context.showStatus(message); });
    connect(m_exports, &HistoryExports::problem, this,
            [this](const QString& title, const QString& text, const QString& details) {
                m_context.showMessage(QMessageBox::Warning, title, text, details);
            });
    connect(this, &DesignWorkspace::sessionChanged, this, &DesignWorkspace::onSessionChanged);
}

void DesignWorkspace::restoreSettings()
{
    const BrushChoices brush = loadBrushChoices(m_context.settings());
    m_brushPanel->setChoices(brush);
    setBrushSettings(m_brushPanel->settings());
    m_brushAction->setChecked(brush.toolEnabled);
    m_timelinePanel->setFps(m_context.settings().value(kDesignFpsKey, 12).toInt());
    m_exports->setFps(m_timelinePanel->fps());
}

void DesignWorkspace::onSessionChanged()
{
    m_brushPanel->setMeshRadius(m_session ? m_session->baseBounds().radius() : 0.0);
    setBrushSettings(m_brushPanel->settings());
    m_timelineDock->setVisible(m_session != nullptr);
}

// The camera is stored in the mesh's object space (the project has no model matrix). The
// base rule is the Render panel's static rule: the window passes it with every change of
// the render choices (setRenderMode).
timeline::ProjectExtras DesignWorkspace::projectExtras() const
{
    timeline::ProjectExtras extras;
    const glm::dmat4 toObject = m_session ? glm::inverse(m_session->modelMatrix()) : glm::dmat4(1.0);
    const Camera camera = m_viewport->camera();
    timeline::ProjectView view;
    view.eye = glm::dvec3(toObject * glm::dvec4(camera.eye, 1.0));
    view.target = glm::dvec3(toObject * glm::dvec4(camera.target, 1.0));
    view.up = glm::normalize(glm::dvec3(toObject * glm::dvec4(camera.up, 0.0)));
    view.fovyDegrees = camera.fovyDegrees;
    extras.view = view;
    extras.staticRule = m_baseRule;
    if (const Document* document = m_context.document().get()) {
        const std::shared_ptr<const LoadedScene> shown = m_context.host().shownScene();
        const Bounds bounds = shown ? shown->scene.worldBounds() : Bounds{};
        extras.staticRule = document->settings().trim.rule;
        extras.viewSettings = timeline::storedViewSettings(document->settings(), bounds);
    }
    return extras;
}

double DesignWorkspace::lastTrimCheckMilliseconds() const
{
    return m_guard->lastCheckMilliseconds();
}

void DesignWorkspace::startSession(timeline::Timeline history, const glm::dmat4& model)
{
    endSession();
    m_session = std::make_unique<DesignSession>(std::move(history), model, *m_context.document().get()->undoStack());
    connect(m_session.get(), &DesignSession::historyChanged, this, &DesignWorkspace::onHistoryChanged);
    // Another frame shown, or the history changed: the frame replaces a foreign pose.
    connect(m_session.get(), &DesignSession::shownFrameChanged, this, &DesignWorkspace::refreshView);
    m_brush->setSession(m_session.get());
    m_brush->setDynamicRules(showsDynamicRules());
    m_points->setSession(m_session.get());
    m_points->setDynamicRules(showsDynamicRules());
    showControlNet();
    m_viewBounds = Bounds{};
    extendViewBounds(m_session->timeline().base().positions);
    for (int f = 1; f < m_session->timeline().frameCount(); ++f)
        extendViewBounds(m_session->timeline().frame(f).after);
    m_viewport->setViewBounds(m_viewBounds);
    refreshView();
    emit sessionChanged();
}

void DesignWorkspace::endSession()
{
    if (!m_session)
        return;
    m_viewport->setFramingPoints({});
    m_brush->setSession(nullptr);
    m_points->setSession(nullptr);
    m_overlay->clearNet();
    m_guard->reset();
    m_session->undoStack()->clear(); // its commands edit the session ending here
    m_session.reset();
    m_shown.showChain(nullptr);
    m_shown.withdrawPose();
    m_chainOfForeignPose = false;
    refreshTimelinePanel();
    emit sessionChanged();
}

Document* DesignWorkspace::document() const
{
    return m_context.document().get();
}

CurrentDocument& DesignWorkspace::currentDocument() const
{
    return m_context.document();
}

bool DesignWorkspace::isModified() const
{
    const Document* document = m_context.document().get();
    return document && document->isModified();
}

void DesignWorkspace::setRenderMode(bool dynamicRules, StaticRule baseRule, bool trimEnabled)
{
    if (dynamicRules == m_dynamicRules && baseRule == m_baseRule && trimEnabled == m_trimEnabled)
        return;
    m_dynamicRules = dynamicRules;
    m_baseRule = baseRule;
    m_trimEnabled = trimEnabled;
    m_brush->setDynamicRules(showsDynamicRules());
    m_points->setDynamicRules(showsDynamicRules());
    refreshChain(); // the pose shown stays, whoever's it is
}

void DesignWorkspace::setBrushSettings(const deform::BrushSettings& settings)
{
    m_brush->setSettings(settings);
}

// Fit and Home frame the net with the surface: its points reach past the surface.
void DesignWorkspace::frameControlNet(const std::vector<glm::dvec3>& points)
{
    std::vector<glm::dvec3> world;
    world.reserve(points.size());
    for (const glm::dvec3& p : points)
        world.push_back(glm::dvec3(m_session->modelMatrix() * glm::dvec4(p, 1.0)));
    m_viewport->setFramingPoints(std::move(world));
}

void DesignWorkspace::showControlNet()
{
    const EditableSurface* surface = m_session ? m_session->surface() : nullptr;
    if (!surface) {
        m_overlay->clearNet();
        m_viewport->setFramingPoints({});
        return;
    }
    std::vector<std::array<std::uint32_t, 2>> edges;
    edges.reserve(surface->netEdges().size());
    for (const ControlNetEdge& edge : surface->netEdges())
        edges.push_back({edge.a, edge.b});
    m_overlay->setNet(surface->controlPoints(), std::move(edges), m_session->modelMatrix());
}

void DesignWorkspace::moveSelectionAlongNormal(double distance)
{
    if (!m_session || !m_session->surface())
        return;
    const std::vector<std::uint32_t>& selection = m_points->selection();
    if (selection.empty()) {
        emit statusMessage(tr("Select control points first (click one; Shift+click adds more)."));
        return;
    }
    if (!m_session->showsLastFrame()) {
        emit statusMessage(tr("Control points edit the last frame only: go to the last frame first."));
        return;
    }
    try {
        m_session->syncSurface();
        const std::vector<ControlPointTarget> targets =
            moveControlPointsAlongNormal(*m_session->surface(), selection, distance);
        if (targets.empty()) {
            emit statusMessage(tr("The selected points have no common normal (they face opposite ways)."));
            return;
        }
        timeline::Frame frame =
            controlEditFrame(*m_session->surface(), targets, m_session->timeline().currentPositions());
        if (const std::optional<QString> refusal = m_guard->refuseControlEdit(*m_session, m_baseRule, frame)) {
            m_session->syncSurface();
            emit statusMessage(*refusal);
            return;
        }
        const int points = int(frame.controlMoves.size());
        m_session->undoStack()->push(new AppendFrameCommand(
            *m_session, std::move(frame),
            tr("Move %1 along the normal").arg(countOf(points, tr("control point"), tr("control points")))));
    } catch (const std::invalid_argument& e) {
        m_session->syncSurface();
        emit statusMessage(tr("No edit recorded: %1").arg(QString::fromStdString(e.what())));
    }
}

void DesignWorkspace::startNewSet(DynamicRule rule)
{
    if (!m_session)
        return;
    m_session->undoStack()->push(new StartSetCommand(*m_session, rule));
    const std::string_view name = dynamicRuleDisplayName(rule);
    emit statusMessage(tr("Set %1 (%2) starts at frame %3: its strokes deform concurrently and must stay disjoint.")
                           .arg(m_session->currentSet() + 1)
                           .arg(QString::fromUtf8(name.data(), qsizetype(name.size())))
                           .arg(m_session->lastFrame()));
}

void DesignWorkspace::chooseRule(DynamicRule rule)
{
    if (!m_session || m_session->timeline().sets().empty())
        return;
    const int set = m_session->currentSet();
    if (m_session->timeline().sets()[std::size_t(set)].rule == rule)
        return;
    m_session->undoStack()->push(new SetRuleCommand(*m_session, set, rule));
}

void DesignWorkspace::showFrame(int frame)
{
    if (m_session)
        m_session->showFrame(frame);
}

void DesignWorkspace::onHistoryChanged()
{
    const timeline::Timeline& history = m_session->timeline();
    if (history.frameCount() > 1) {
        const Bounds before = m_viewBounds;
        extendViewBounds(history.frame(history.frameCount() - 1).after);
        if (m_viewBounds.min != before.min || m_viewBounds.max != before.max)
            m_viewport->setViewBounds(m_viewBounds); // a stroke reached past every earlier frame
    }
    refreshView();
}

void DesignWorkspace::extendViewBounds(const std::vector<glm::vec3>& positions)
{
    const glm::dmat4& model = m_session->modelMatrix();
    for (const glm::vec3& p : positions)
        m_viewBounds.extend(glm::dvec3(model * glm::dvec4(glm::dvec3(p), 1.0)));
}

// The history's shown frame becomes the pose shown (replacing another feature's pose),
// and under the dynamic rules the chain to it.
void DesignWorkspace::refreshView()
{
    refreshTimelinePanel();
    if (!m_session)
        return;
    if (const EditableSurface* surface = m_session->surface()) {
        m_overlay->setPoints(surface->controlPoints());
        frameControlNet(surface->controlPoints());
    }
    m_showingFrame = true;
    m_shown.showPose(m_session->shownPositions());
    m_showingFrame = false;
    refreshChain();
}

void DesignWorkspace::refreshChain()
{
    if (!m_session || !showsDynamicRules()) {
        m_shown.showChain(nullptr);
        m_chainOfForeignPose = false;
        return;
    }
    m_chainOfForeignPose = foreignPose() != nullptr;
    m_shown.showChain(std::make_shared<const DynamicChain>(shownChain()));
}

// Another feature posed the designed mesh (or gave the view back to the history's frame):
// the chain must end in what is shown. The history's own drags replace the shown level
// themselves, and refreshView builds the chain after publishing the frame.
void DesignWorkspace::onShownPoseChanged()
{
    if (m_session && !m_showingFrame && (foreignPose() || m_chainOfForeignPose))
        refreshChain();
}

// The pose shown on the designed mesh when it is another feature's, else nullptr.
const std::vector<glm::vec3>* DesignWorkspace::foreignPose() const
{
    const render::ShownContent& content = *m_shown.content();
    const render::ShownPose* pose = content.pose();
    if (!m_session || !pose || content.poseOwner() == render::ContentOwner::DesignHistory ||
        pose->positions.size() != m_session->timeline().base().positions.size())
        return nullptr;
    return &pose->positions;
}

// The chain to the shown frame; with a foreign pose its last level deforms the current
// set's reference into the pose (the pose is one more deformation of that set), so the
// dynamic rules classify what the view shows.
DynamicChain DesignWorkspace::shownChain() const
{
    const timeline::Timeline& history = m_session->timeline();
    DynamicChain chain = dynamicChainTo(history, m_session->shownFrame(), m_baseRule, m_session->modelMatrix());
    const std::vector<glm::vec3>* foreign = foreignPose();
    if (!foreign)
        return chain;
    const timeline::Timeline::ChainLink last = history.chainTo(m_session->shownFrame()).back();
    chain.levels.back() = dynamicShownLevel(history, history.positionsAt(last.referenceFrame), *foreign, last.rule,
                                            m_session->modelMatrix());
    return chain;
}

void DesignWorkspace::refreshTimelinePanel()
{
    if (m_session)
        m_timelinePanel->setHistory(&m_session->timeline(), m_session->shownFrame());
    else
        m_timelinePanel->setHistory(nullptr, 0);
}

} // namespace trimlab::ui
