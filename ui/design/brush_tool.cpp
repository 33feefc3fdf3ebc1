#include "ui/design/brush_tool.h"

#include "ui/common/count_text.h"
#include "ui/common/glm_points.h"

#include "ui/design/control_brush_drag.h"
#include "core/image/packed_rgba8.h"
#include "ui/design/append_frame_command.h"
#include "ui/design/design_session.h"
#include "core/trim/trim_shading.h"
#include "ui/viewport/viewport_widget.h"

#include <glm/common.hpp>

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QUndoStack>

#include <cmath>
#include <stdexcept>

namespace trimlab::ui {

namespace {

QString vertexCount(std::size_t count)
{
    return countOf((long long)count, BrushTool::tr("vertex"), BrushTool::tr("vertices"));
}

QString controlPointCount(int count)
{
    return countOf(count, BrushTool::tr("control point"), BrushTool::tr("control points"));
}

/// The hue the brush region is tinted toward (a magenta the trim palette does not use).
constexpr glm::vec3 kRegionColor{0.86f, 0.22f, 0.52f};
/// Tint at the region's rim (falloff 0), so the whole geodesic disc stays visible.
constexpr float kRimTint = 0.3f;

/// Per-vertex colors: the front-facing trim color, tinted toward kRegionColor inside the
/// region by the falloff weight.
std::vector<std::uint32_t> regionTint(std::size_t vertexCount, const deform::InfluenceRegion& region)
{
    std::vector<std::uint32_t> colors(vertexCount, packRgba8(kFrontFacingColor));
    for (std::size_t i = 0; i < region.vertices.size(); ++i) {
        const float weight = kRimTint + (1.0f - kRimTint) * float(region.falloff[i]);
        colors[region.vertices[i]] = packRgba8(glm::mix(kFrontFacingColor, kRegionColor, weight));
    }
    return colors;
}

} // namespace

BrushTool::BrushTool(ViewportWidget* viewport, QObject* parent)
    : QObject(parent),
      m_viewport(viewport),
      m_shown(viewport->content(), render::ContentOwner::DesignHistory),
      m_tint(viewport->content(), render::ContentOwner::BrushRegion)
{
    m_hoverTimer.setSingleShot(true);
    m_hoverTimer.setInterval(kHoverIntervalMs);
    connect(&m_hoverTimer, &QTimer::timeout, this, &BrushTool::updateHoverRegion);
}

BrushTool::~BrushTool()
{
    if (m_enabled && m_viewport->tool() == this)
        m_viewport->setTool(nullptr);
}

void BrushTool::setSession(DesignSession* session)
{
    m_drag.reset();
    m_controlDrag.reset();
    clearRegionTint();
    m_session = session;
    // Without a history there is nothing to deform: the mouse is the camera's again (and
    // the view's tooltip says so) until a history is shown with the brush still on.
    if (m_enabled)
        m_viewport->offerTool(this, m_session != nullptr);
}

void BrushTool::setSettings(const deform::BrushSettings& settings)
{
    m_settings = settings;
    m_hoverTriangle.reset(); // the region changes with the radius and profile
}

void BrushTool::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    m_drag.reset();
    if (m_controlDrag && m_session)
        m_session->syncSurface();
    m_controlDrag.reset();
    m_hoverTimer.stop();
    clearRegionTint();
    // Another tool may have taken the viewport already (Edit ▸ Control Points): leave it.
    if (enabled && m_session)
        m_viewport->setTool(this);
    else if (m_viewport->tool() == this)
        m_viewport->setTool(nullptr);
}

void BrushTool::setDynamicRules(bool dynamic)
{
    m_dynamic = dynamic;
    clearRegionTint(); // picked again from the next frame, whose ids are the other rules'
}

std::optional<QString> BrushTool::refusalBeforePick() const
{
    if (m_session->showsLastFrame())
        return std::nullopt;
    return tr("The brush edits the last frame only; frame %1 of %2 is shown. Go to the last frame (End on the "
              "timeline slider) to continue the history, or undo back to this frame to change it.")
        .arg(m_session->shownFrame())
        .arg(m_session->lastFrame());
}

// The surface point under `position`, from the last frame's trim image: its triangle
// (mapped through the dynamic scene's meshTriangle when that frame was dynamic) and depth.
std::optional<BrushPick> BrushTool::pickAt(QPointF position)
{
    const std::optional<TrimPixel> pixel = m_viewport->trimPixelAt(position);
    const auto& frame = m_viewport->lastFrame();
    if (!pixel || !frame)
        return std::nullopt;
    const render::ShownChain* chain = m_viewport->content()->chain();
    const DynamicChainLevel* level = m_viewport->lastDynamicStats() && chain ? &chain->shownLevel() : nullptr;
    const std::optional<std::uint32_t> triangle = pickedTriangle(*pixel, level ? &level->frame : nullptr);
    const std::vector<glm::uvec3>& triangles = m_session->timeline().base().triangles;
    if (!triangle || *triangle >= triangles.size() || !std::isfinite(pixel->viewDepth))
        return std::nullopt;
    const DragView view{frame->camera, toGlm(frame->pixelSize)};
    return pickAnchor(view, toGlm(m_viewport->devicePosition(position)), *triangle, double(pixel->viewDepth),
                      m_session->shownPositions(), triangles, m_session->modelMatrix());
}

bool BrushTool::pressed(QMouseEvent& event)
{
    if (!m_enabled || !m_session || event.button() != Qt::LeftButton || (event.modifiers() & Qt::AltModifier))
        return false;
    const std::optional<BrushPick> pick = pickAt(event.position());
    if (!pick)
        return false; // the background: the camera moves as without the brush
    if (const std::optional<QString> refusal = refusalBeforePick()) {
        emit statusMessage(*refusal);
        return true;
    }
    if (m_session->surface())
        return startControlDrag(*pick);
    const timeline::Timeline& history = m_session->timeline();
    const DragView view{m_viewport->lastFrame()->camera, toGlm(m_viewport->lastFrame()->pixelSize)};
    try {
        m_drag = std::make_unique<BrushDrag>(m_session->topology(), history.currentPositions(), view, *pick, m_settings,
                                             m_session->modelMatrix());
    } catch (const std::invalid_argument& e) {
        emit statusMessage(tr("The brush cannot start: %1").arg(QString::fromStdString(e.what())));
        return true;
    }
    if (m_guard) {
        if (const std::optional<QString> refusal = m_guard(*m_drag)) {
            m_drag.reset();
            emit statusMessage(*refusal);
            return true;
        }
    }
    rememberDragStart();
    return true;
}

// What a drag must know at its start: the frame count (a history changed meanwhile
// discards the stroke) and, under the dynamic rules, the current set's reference.
void BrushTool::rememberDragStart()
{
    const timeline::Timeline& history = m_session->timeline();
    m_dragFrameCount = history.frameCount();
    if (m_dynamic) {
        const timeline::DeformationSet& set = history.sets().back();
        m_dragReference = history.positionsAt(set.referenceFrame());
        m_dragRule = set.rule;
    }
}

// The control points of an editable surface: the same pick and drag, other targets.
bool BrushTool::startControlDrag(const BrushPick& pick)
{
    const DragView view{m_viewport->lastFrame()->camera, toGlm(m_viewport->lastFrame()->pixelSize)};
    m_session->syncSurface();
    try {
        m_controlDrag = std::make_unique<ControlBrushDrag>(*m_session, view, pick, m_settings);
    } catch (const std::exception& e) {
        emit statusMessage(tr("The brush cannot start: %1").arg(QString::fromStdString(e.what())));
        return true;
    }
    rememberDragStart();
    return true;
}

void BrushTool::moved(QMouseEvent& event)
{
    if (!m_drag && !m_controlDrag)
        return;
    QElapsedTimer timer;
    timer.start();
    const bool alongNormal = event.modifiers() & Qt::ShiftModifier;
    const glm::dvec2 pixel = toGlm(m_viewport->devicePosition(event.position()));
    try {
        showDragPositions(m_drag ? m_drag->moveTo(pixel, alongNormal) : m_controlDrag->moveTo(pixel, alongNormal));
    } catch (const std::exception& e) {
        emit statusMessage(tr("The brush cannot move the control points: %1").arg(QString::fromStdString(e.what())));
    }
    m_lastUpdateMs = double(timer.nsecsElapsed()) * 1e-6;
}

// The positions are the pose shown (the static path uploads them at its next frame).
// Under the dynamic rules only the chain's shown level is rebuilt besides; the earlier
// sets' characterizations stay cached.
void BrushTool::showDragPositions(const std::vector<glm::vec3>& positions)
{
    m_shown.showPose(positions);
    if (m_dynamic && m_shown.showsChain())
        m_shown.replaceShownLevel(std::make_shared<const DynamicChainLevel>(dynamicShownLevelOf(positions)));
}

DynamicChainLevel BrushTool::dynamicShownLevelOf(const std::vector<glm::vec3>& positions) const
{
    return {makeDynamicFrameScene(m_session->timeline().base().triangles, m_dragReference, positions,
                                  m_session->modelMatrix()),
            m_dragRule};
}

void BrushTool::released(QMouseEvent&)
{
    if (m_controlDrag) {
        releaseControlDrag();
        return;
    }
    const std::unique_ptr<BrushDrag> drag = std::move(m_drag);
    if (!drag || !drag->moved() || !m_session)
        return;
    if (m_session->timeline().frameCount() != m_dragFrameCount) {
        emit statusMessage(tr("The stroke was discarded: the history changed during the drag."));
        return;
    }
    timeline::Frame frame = drag->frame();
    const std::size_t moved = frame.vertices.size();
    m_session->undoStack()->push(
        new AppendFrameCommand(*m_session, std::move(frame), tr("Stroke (%1)").arg(vertexCount(moved))));
    emit statusMessage(tr("Stroke %1: %2 moved.").arg(m_session->lastFrame()).arg(vertexCount(moved)));
}

void BrushTool::releaseControlDrag()
{
    const std::unique_ptr<ControlBrushDrag> drag = std::move(m_controlDrag);
    if (!m_session)
        return;
    const std::vector<ControlPointTarget> targets = drag->targets();
    m_session->syncSurface(); // back at the history's control points, where the frame starts
    if (!drag->moved() || targets.empty()) {
        m_shown.showPose(m_session->shownPositions());
        if (drag->moved() && drag->nearestControlPoint() >= drag->radius())
            emit statusMessage(tr("The brush reached no control point: the nearest is %1 from where you pressed, "
                                  "beyond the radius %2. Widen the radius in the Brush panel.")
                                   .arg(drag->nearestControlPoint(), 0, 'g', 3)
                                   .arg(drag->radius(), 0, 'g', 3));
        return;
    }
    if (m_session->timeline().frameCount() != m_dragFrameCount) {
        emit statusMessage(tr("The stroke was discarded: the history changed during the drag."));
        return;
    }
    try {
        timeline::Frame frame =
            controlEditFrame(*m_session->surface(), targets, m_session->timeline().currentPositions());
        if (m_controlGuard) {
            if (const std::optional<QString> refusal = m_controlGuard(frame)) {
                m_session->syncSurface();
                m_shown.showPose(m_session->shownPositions());
                emit statusMessage(*refusal);
                return;
            }
        }
        const int points = int(frame.controlMoves.size());
        m_session->undoStack()->push(
            new AppendFrameCommand(*m_session, std::move(frame), tr("Brush on %1").arg(controlPointCount(points))));
        emit statusMessage(
            tr("Frame %1: the brush moved %2.").arg(m_session->lastFrame()).arg(controlPointCount(points)));
    } catch (const std::invalid_argument& e) {
        m_session->syncSurface();
        m_shown.showPose(m_session->shownPositions());
        emit statusMessage(tr("No edit recorded: %1").arg(QString::fromStdString(e.what())));
    }
}

void BrushTool::hovered(QPointF position)
{
    if (!m_enabled || !m_session || m_drag || m_controlDrag || m_session->surface())
        return;
    m_hoverPosition = position;
    if (!m_hoverTimer.isActive())
        m_hoverTimer.start();
}

void BrushTool::left()
{
    m_hoverTimer.stop();
    clearRegionTint();
}

// Throttled by m_hoverTimer; rebuilds the region only when another triangle is hovered
// (a BrushStroke costs a few ms on 100k vertices).
void BrushTool::updateHoverRegion()
{
    if (!m_enabled || !m_session || m_drag || !m_session->showsLastFrame()) {
        clearRegionTint();
        return;
    }
    const std::optional<BrushPick> pick = pickAt(m_hoverPosition);
    if (!pick) {
        clearRegionTint();
        return;
    }
    if (m_hoverTriangle == pick->triangle)
        return;
    try {
        const deform::BrushStroke stroke(m_session->topology(), m_session->timeline().currentPositions(),
                                         deform::Stroke{pick->anchor, pick->triangle, glm::dvec3(0.0), m_settings});
        m_tint.showColors(regionTint(m_session->topology().vertexCount(), stroke.region()));
        m_hoverTriangle = pick->triangle;
        m_tinted = true;
    } catch (const std::invalid_argument&) {
        clearRegionTint(); // settings the brush refuses: the press will say why
    }
}

void BrushTool::clearRegionTint()
{
    m_hoverTriangle.reset();
    if (!m_tinted)
        return;
    m_tinted = false;
    m_tint.showColors({});
}

QString BrushTool::mouseHelp() const
{
    return tr("Drag on the surface: deform it in the view plane (Shift: along the surface normal) · Drag on the "
              "background or Alt+drag: orbit · Right/middle drag: pan · Wheel: zoom");
}

} // namespace trimlab::ui
