#include "design_workspace.h"

#include "brush_tool.h"
#include "append_frame_command.h"
#include "control_net_overlay.h"
#include "control_point_tool.h"
#include "deformation_timeline_panel.h"
#include "design_session.h"
#include "session_chain.h"
#include "set_rule_command.h"
#include "start_set_command.h"
#include "trimmed_region_check.h"
#include "viewport_widget.h"

#include "surface/control_brush.h"

#include <QElapsedTimer>
#include <QUndoGroup>
#include <QUndoStack>

namespace trimlab::ui {

namespace {

/// How far inside the surface a trim test ray starts, relative to the mesh's bounding
/// radius: far above float rounding of the positions, far below any feature.
constexpr double kTrimTestOffset = 1e-5;

} // namespace

DesignWorkspace::DesignWorkspace(ViewportWidget* viewport, DeformationTimelinePanel* timelinePanel, QObject* parent)
    : QObject(parent),
      m_viewport(viewport),
      m_timelinePanel(timelinePanel),
      m_undoGroup(new QUndoGroup(this)),
      m_brush(new BrushTool(viewport, this)),
      m_overlay(new ControlNetOverlay(viewport)),
      m_points(new ControlPointTool(viewport, m_overlay, this))
{
    m_brush->setGuard([this](const BrushDrag& drag) { return trimmedRegionRefusal(drag); });
    connect(m_brush, &BrushTool::statusMessage, this, &DesignWorkspace::statusMessage);
    connect(m_points, &ControlPointTool::statusMessage, this, &DesignWorkspace::statusMessage);
    m_points->setViewRestorer([this] { refreshView(); });
    m_points->setGuard([this](const timeline::Frame& frame) { return controlEditRefusal(frame); });
    m_brush->setControlGuard([this](const timeline::Frame& frame) { return controlEditRefusal(frame); });
    connect(m_timelinePanel, &DeformationTimelinePanel::frameChosen, this, &DesignWorkspace::showFrame);
    connect(m_timelinePanel, &DeformationTimelinePanel::newSetRequested, this, &DesignWorkspace::startNewSet);
    connect(m_timelinePanel, &DeformationTimelinePanel::ruleChosen, this, &DesignWorkspace::chooseRule);
}

DesignWorkspace::~DesignWorkspace()
{
    m_brush->setSession(nullptr);
    m_points->setSession(nullptr);
}

void DesignWorkspace::startSession(timeline::Timeline history, const glm::dmat4& model, const QString& projectPath)
{
    endSession();
    m_session = std::make_unique<DesignSession>(std::move(history), model, projectPath);
    QUndoStack* stack = m_session->undoStack();
    m_undoGroup->addStack(stack);
    m_undoGroup->setActiveStack(stack);
    connect(stack, &QUndoStack::cleanChanged, this, [this](bool clean) { emit modifiedChanged(!clean); });
    connect(m_session.get(), &DesignSession::historyChanged, this, &DesignWorkspace::onHistoryChanged);
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
    emit modifiedChanged(false);
}

void DesignWorkspace::endSession()
{
    if (!m_session)
        return;
    m_brush->setSession(nullptr);
    m_points->setSession(nullptr);
    m_overlay->clearNet();
    m_check.reset();
    m_undoGroup->removeStack(m_session->undoStack());
    m_session.reset();
    m_viewport->setDynamicChain(nullptr);
    refreshTimelinePanel();
    emit sessionChanged();
    emit modifiedChanged(false);
}

bool DesignWorkspace::isModified() const
{
    return m_session && !m_session->undoStack()->isClean();
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
    refreshView();
}

void DesignWorkspace::setBrushSettings(const deform::BrushSettings& settings)
{
    m_brush->setSettings(settings);
}

void DesignWorkspace::showControlNet()
{
    const EditableSurface* surface = m_session ? m_session->surface() : nullptr;
    if (!surface) {
        m_overlay->clearNet();
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
        if (const std::optional<QString> refusal = controlEditRefusal(frame)) {
            m_session->syncSurface();
            emit statusMessage(*refusal);
            return;
        }
        const int points = int(frame.controlMoves.size());
        m_session->undoStack()->push(new AppendFrameCommand(
            *m_session, std::move(frame), tr("Move %n control point(s) along the normal", nullptr, points)));
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

// The viewport always gets the shown positions (the static path and the pose the trim
// image is picked from); under the dynamic rules also the chain to the shown frame.
void DesignWorkspace::refreshView()
{
    refreshTimelinePanel();
    if (!m_session)
        return;
    if (const EditableSurface* surface = m_session->surface())
        m_overlay->setPoints(surface->controlPoints());
    m_viewport->showPose(m_session->shownPositions());
    if (!showsDynamicRules()) {
        m_viewport->setDynamicChain(nullptr);
        return;
    }
    m_viewport->setDynamicChain(std::make_shared<const DynamicChain>(dynamicChainTo(
        m_session->timeline(), m_session->shownFrame(), m_baseRule, m_session->modelMatrix())));
}

void DesignWorkspace::refreshTimelinePanel()
{
    if (m_session)
        m_timelinePanel->setHistory(&m_session->timeline(), m_session->shownFrame());
    else
        m_timelinePanel->setHistory(nullptr, 0);
}

// The homogeneous confluent rule: refuse a drag whose region reaches a trimmed-off part
// of the last frame. The exact CPU check is built once per history revision.
std::optional<QString> DesignWorkspace::trimmedRegionRefusal(const BrushDrag& drag)
{
    return trimmedSampleRefusal(TrimmedRegionCheck::sample(
        drag.stroke().region().vertices, m_session->timeline().base().triangles.at(drag.pick().triangle)));
}

// A control edit is judged on exactly the vertices it moves (known once its frame is
// built, at the release); the first of them stands in for the brush's grabbed triangle.
std::optional<QString> DesignWorkspace::controlEditRefusal(const timeline::Frame& frame)
{
    if (frame.vertices.empty())
        return std::nullopt;
    const std::uint32_t first = frame.vertices.front();
    return trimmedSampleRefusal(TrimmedRegionCheck::sample(frame.vertices, glm::uvec3(first)));
}

std::optional<QString> DesignWorkspace::trimmedSampleRefusal(const std::vector<std::uint32_t>& sample)
{
    const timeline::Timeline& history = m_session->timeline();
    if (history.sets().empty() || !forbidsDeformingTrimmedParts(history.sets().back().rule))
        return std::nullopt;
    QElapsedTimer timer;
    timer.start();
    if (!m_check || m_checkRevision != m_session->revision() || m_checkBaseRule != m_baseRule) {
        m_check = std::make_unique<TrimmedRegionCheck>(
            dynamicChainTo(history, m_session->lastFrame(), m_baseRule, m_session->modelMatrix()),
            m_session->modelMatrix());
        m_checkRevision = m_session->revision();
        m_checkBaseRule = m_baseRule;
    }
    const std::vector<std::uint32_t> off = m_check->trimmedOff(
        m_session->topology(), history.currentPositions(), sample, kTrimTestOffset * m_session->baseBounds().radius());
    m_lastCheckMs = double(timer.nsecsElapsed()) * 1e-6;
    if (off.empty())
        return std::nullopt;
    return tr("Homogeneous confluent rule: this part was trimmed off and may not be deformed (thesis 8.1.1). Start a "
              "new set with another rule to deform it.");
}

} // namespace trimlab::ui
