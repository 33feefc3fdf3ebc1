#include "ui/design/control_point_tool.h"

#include "ui/common/count_text.h"
#include "ui/common/glm_points.h"

#include "ui/design/append_frame_command.h"
#include "ui/design/control_net_overlay.h"
#include "core/design/control_point_pick.h"
#include "core/design/control_preview.h"
#include "ui/design/design_session.h"
#include "ui/viewport/viewport_widget.h"

#include "core/design/control_brush.h"
#include "core/trim/dynamic_frame_scene.h"

#include <glm/geometric.hpp>

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace trimlab::ui {

ControlPointTool::ControlPointTool(ViewportWidget* viewport, ControlNetOverlay* overlay, QObject* parent)
    : QObject(parent),
      m_viewport(viewport),
      m_overlay(overlay),
      m_shown(viewport->content(), render::ContentOwner::DesignHistory)
{
}

ControlPointTool::~ControlPointTool()
{
    if (m_enabled && m_viewport->tool() == this)
        m_viewport->setTool(nullptr);
}

void ControlPointTool::setSession(DesignSession* session)
{
    cancelDrag();
    m_session = session;
    setSelection({});
    // Without a history there are no control points to pick: the mouse is the camera's.
    if (m_enabled)
        m_viewport->offerTool(this, m_session != nullptr);
}

void ControlPointTool::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    cancelDrag();
    m_enabled = enabled;
    m_overlay->setHovered(std::nullopt);
    // The brush may have taken the viewport already: leave it.
    if (enabled && m_session)
        m_viewport->setTool(this);
    else if (m_viewport->tool() == this)
        m_viewport->setTool(nullptr);
}

void ControlPointTool::setSelection(std::vector<std::uint32_t> selection)
{
    std::sort(selection.begin(), selection.end());
    selection.erase(std::unique(selection.begin(), selection.end()), selection.end());
    const std::size_t count = m_session && m_session->surface() ? m_session->surface()->controlPointCount() : 0;
    std::erase_if(selection, [count](std::uint32_t i) { return i >= count; });
    if (selection == m_selection)
        return;
    m_selection = std::move(selection);
    m_overlay->setSelection(m_selection);
    emit selectionChanged(int(m_selection.size()));
}

bool ControlPointTool::pressed(QMouseEvent& event)
{
    if (!m_enabled || !m_session || !m_session->surface() || event.button() != Qt::LeftButton ||
        (event.modifiers() & Qt::AltModifier) || !m_overlay->isVisible())
        return false;
    const std::vector<std::optional<QPointF>> points = m_overlay->projectedPoints();
    const std::optional<std::uint32_t> picked = nearestPoint(toGlm(event.position()), toGlm(points), kPickPixels);
    const bool toggle = event.modifiers() & Qt::ShiftModifier;
    if (!picked && (event.modifiers() & Qt::ControlModifier)) {
        m_boxStart = event.position(); // box selection (the camera keeps still)
        return true;
    }
    if (!picked || toggle) {
        setSelection(clickedSelection(m_selection, picked, toggle));
        return picked.has_value(); // empty space: the camera still orbits or pans
    }
    if (!std::binary_search(m_selection.begin(), m_selection.end(), *picked))
        setSelection({*picked});
    if (!m_session->showsLastFrame()) {
        emit statusMessage(tr("Control points edit the last frame only; frame %1 of %2 is shown. Go to the last "
                              "frame (End on the timeline slider) to continue the history.")
                               .arg(m_session->shownFrame())
                               .arg(m_session->lastFrame()));
        return true;
    }
    // A refused drag still takes the press: the click selected a point.
    (void)startDrag(*picked, event.position(), event.modifiers() & Qt::ControlModifier);
    return true;
}

// The grabbed point fixes the depth of the view-plane drag; the selection's average
// normal (taken once, at the press) the direction of a Ctrl drag.
// The points projected inside `box` join the selection (a box selection adds, as Shift
// + click does).
void ControlPointTool::selectInBox(const QRectF& box)
{
    m_overlay->setSelectionBox(std::nullopt);
    const std::vector<std::optional<QPointF>> points = m_overlay->projectedPoints();
    std::vector<std::uint32_t> selection = m_selection;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        if (points[i] && box.contains(*points[i]))
            selection.push_back(i);
    std::sort(selection.begin(), selection.end());
    selection.erase(std::unique(selection.begin(), selection.end()), selection.end());
    const std::size_t added = selection.size() - m_selection.size();
    setSelection(std::move(selection));
    emit statusMessage(tr("The box added %1; %2 selected.")
                           .arg(countOf(qint64(added), tr("control point"), tr("control points")))
                           .arg(m_selection.size()));
}

bool ControlPointTool::startDrag(std::uint32_t grabbed, QPointF position, bool alongNormal)
{
    const auto& frame = m_viewport->lastFrame();
    if (!frame)
        return false;
    m_view = DragView{m_viewport->camera(), toGlm(m_viewport->framePixelSize())};
    const glm::dvec3 world = m_overlay->worldPoint(grabbed);
    const glm::dvec3 forward = glm::normalize(m_view.camera.target - m_view.camera.eye);
    m_grab = BrushPick{0, m_session->surface()->controlPoints()[grabbed], glm::dot(world - m_view.camera.eye, forward),
                       toGlm(m_viewport->devicePosition(position))};
    m_alongNormal = alongNormal;
    m_normal = glm::dvec3(0.0);
    if (alongNormal) {
        for (std::uint32_t i : m_selection)
            m_normal += m_session->surface()->controlPointNormal(i);
        const double length = glm::length(m_normal);
        if (!(length > 0.0)) {
            emit statusMessage(tr("The selected points have no common normal (they face opposite ways): drag "
                                  "without Ctrl to move them in the view plane."));
            return false;
        }
        m_normal /= length;
    }
    const timeline::Timeline& history = m_session->timeline();
    m_dragFrameCount = history.frameCount();
    if (m_dynamic) {
        const timeline::DeformationSet& set = history.sets().back();
        m_dragReference = history.positionsAt(set.referenceFrame());
        m_dragRule = set.rule;
    }
    m_session->syncSurface();
    // The selection with its tied points, where they are now: each move offsets these
    // (the preview moves the surface's points, which must not compound the drag).
    m_start = translateControlPoints(*m_session->surface(), m_selection, glm::dvec3(0.0));
    m_preview = std::make_unique<ControlPreview>(*m_session->surface(), history.currentPositions());
    updateGpuStencils();
    m_dragging = true;
    m_dragMoved = false;
    m_targets.clear();
    return true;
}

std::vector<ControlPointTarget> ControlPointTool::targetsFor(QPointF position) const
{
    const glm::dvec3 drag = dragVector(m_view, m_grab, toGlm(m_viewport->devicePosition(position)), m_alongNormal,
                                       m_normal, m_session->modelMatrix());
    if (!std::isfinite(drag.x) || !std::isfinite(drag.y) || !std::isfinite(drag.z))
        throw std::invalid_argument("the drag is not finite (is the grabbed point behind the eye?)");
    std::vector<ControlPointTarget> targets = m_start;
    for (ControlPointTarget& target : targets)
        target.position += drag;
    return targets;
}

void ControlPointTool::moved(QMouseEvent& event)
{
    if (m_boxStart) {
        m_overlay->setSelectionBox(QRectF(*m_boxStart, event.position()).normalized());
        return;
    }
    if (!m_dragging || !m_session)
        return;
    QElapsedTimer timer;
    timer.start();
    try {
        std::vector<ControlPointTarget> targets = targetsFor(event.position());
        preview(targets);
        m_targets = std::move(targets);
        m_dragMoved = true;
    } catch (const std::exception& e) {
        emit statusMessage(tr("Cannot move the control points: %1").arg(QString::fromStdString(e.what())));
    }
    m_lastUpdateMs = double(timer.nsecsElapsed()) * 1e-6;
}

void ControlPointTool::preview(const std::vector<ControlPointTarget>& targets)
{
    // Targets are absolute positions (start + the drag so far), so no drift accumulates
    // over the moves of one drag.
    showPreviewPositions(m_preview->update(targets));
    m_overlay->setPoints(m_session->surface()->controlPoints());
}

// The preview is the pose shown (a subdivision surface evaluated on the GPU from its
// control points where it can be); under the dynamic rules it also replaces the chain's
// shown level.
void ControlPointTool::showPreviewPositions(const std::vector<glm::vec3>& positions)
{
    if (m_gpuStencils)
        m_shown.showSubdivisionPose(m_gpuStencils, m_session->surface()->controlPoints(), positions);
    else
        m_shown.showPose(positions);
    if (m_dynamic && m_shown.showsChain())
        m_shown.replaceShownLevel(std::make_shared<const DynamicChainLevel>(
            DynamicChainLevel{makeDynamicFrameScene(m_session->timeline().base().triangles, m_dragReference, positions,
                                                    m_session->modelMatrix()),
                              m_dragRule}));
}

// Stencils are copied once per surface: a drag of the same surface reuses them, and the
// viewport keeps the GPU objects made from them.
void ControlPointTool::updateGpuStencils()
{
    const EditableSurface& surface = *m_session->surface();
    if (!surface.subdivision()) {
        m_gpuStencils.reset();
        m_gpuStencilsOf.reset();
        return;
    }
    const SubdivisionDefinition& definition = surface.definition().subdivision();
    if (m_gpuStencils && m_gpuStencilsOf && *m_gpuStencilsOf == definition)
        return;
    m_gpuStencils =
        std::make_shared<const render::SubdivisionStencils>(render::subdivisionStencils(*surface.subdivision()));
    m_gpuStencilsOf = definition;
}

void ControlPointTool::released(QMouseEvent& event)
{
    if (m_boxStart) {
        selectInBox(QRectF(*std::exchange(m_boxStart, std::nullopt), event.position()).normalized());
        return;
    }
    if (!m_dragging)
        return;
    m_dragging = false;
    m_preview.reset();
    const std::vector<ControlPointTarget> targets = std::move(m_targets);
    m_targets.clear();
    if (!m_session)
        return;
    if (!m_dragMoved || targets.empty()) {
        endPreview();
        return;
    }
    if (m_session->timeline().frameCount() != m_dragFrameCount) {
        endPreview();
        emit statusMessage(tr("The edit was discarded: the history changed during the drag."));
        return;
    }
    commit(targets);
}

void ControlPointTool::commit(const std::vector<ControlPointTarget>& targets)
{
    m_session->syncSurface(); // controlEditFrame starts from the history's control points
    try {
        timeline::Frame frame =
            controlEditFrame(*m_session->surface(), targets, m_session->timeline().currentPositions());
        if (m_guard) {
            if (const std::optional<QString> refusal = m_guard(frame)) {
                endPreview();
                emit statusMessage(*refusal);
                return;
            }
        }
        const int points = int(frame.controlMoves.size());
        const int vertices = int(frame.vertices.size());
        m_session->undoStack()->push(
            new AppendFrameCommand(*m_session, std::move(frame),
                                   tr("Move %1").arg(countOf(points, tr("control point"), tr("control points")))));
        emit statusMessage(tr("Frame %1: %2 control points moved, %3 vertices changed.")
                               .arg(m_session->lastFrame())
                               .arg(points)
                               .arg(vertices));
    } catch (const std::invalid_argument& e) {
        endPreview();
        emit statusMessage(tr("No edit recorded: %1").arg(QString::fromStdString(e.what())));
    }
}

void ControlPointTool::cancelDrag()
{
    if (!m_dragging)
        return;
    m_dragging = false;
    m_preview.reset();
    m_targets.clear();
    if (m_session)
        endPreview();
}

// The preview left the surface, the net and the view at moved points: back to the history.
void ControlPointTool::endPreview()
{
    m_session->syncSurface();
    m_overlay->setPoints(m_session->surface()->controlPoints());
    if (m_restoreView)
        m_restoreView();
}

void ControlPointTool::hovered(QPointF position)
{
    if (!m_enabled || !m_session || !m_session->surface() || m_dragging || !m_overlay->isVisible())
        return;
    const std::vector<std::optional<QPointF>> points = m_overlay->projectedPoints();
    m_overlay->setHovered(nearestPoint(toGlm(position), toGlm(points), kPickPixels));
}

void ControlPointTool::left()
{
    m_overlay->setHovered(std::nullopt);
}

QString ControlPointTool::mouseHelp() const
{
    return tr("Click a control point: select it (Shift: add to the selection) · Drag a point: move the selection "
              "(Ctrl: along the normal) · Ctrl+drag elsewhere: box select · Drag elsewhere: orbit · Right/middle drag: "
              "pan · Wheel: zoom");
}

} // namespace trimlab::ui
