#include "ui/skeleton/skeleton_pose_tool.h"

#include "ui/skeleton/skeleton_overlay.h"
#include "ui/viewport/widget_projection.h"
#include "ui/viewport/viewport_widget.h"

#include <QMouseEvent>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace trimlab::ui {

namespace {

double angleAround(QPointF centre, QPointF p)
{
    return std::atan2(p.y() - centre.y(), p.x() - centre.x());
}

} // namespace

SkeletonPoseTool::SkeletonPoseTool(ViewportWidget* viewport, SkeletonOverlay* overlay, QObject* parent)
    : QObject(parent), m_viewport(viewport), m_overlay(overlay)
{
}

bool SkeletonPoseTool::pressed(QMouseEvent& event)
{
    if (event.button() != Qt::LeftButton || event.modifiers() != Qt::NoModifier)
        return false;
    const std::vector<std::optional<QPointF>> points = m_overlay->projectedJoints();
    const int bone = nearestSegment(event.position(), points, m_overlay->bones(), kPickPixels);
    if (bone < 0)
        return false;
    m_bone = bone;
    m_head = *points[std::size_t(m_overlay->bones()[std::size_t(bone)][0])];
    m_lastAngle = angleAround(m_head, event.position());
    emit boneSelected(bone);
    return true;
}

void SkeletonPoseTool::moved(QMouseEvent& event)
{
    if (m_bone < 0)
        return;
    const double angle = angleAround(m_head, event.position());
    double delta = std::remainder(angle - m_lastAngle, 2.0 * std::numbers::pi);
    m_lastAngle = angle;
    if (delta == 0.0 || !std::isfinite(delta))
        return;
    // Widget y points down, so a growing atan2 angle is clockwise on screen: a right-handed
    // turn about the axis pointing into the screen (the view direction).
    const Camera camera = m_viewport->camera();
    emit rotateRequested(m_bone, glm::normalize(camera.target - camera.eye), delta);
}

void SkeletonPoseTool::released(QMouseEvent&)
{
    m_bone = -1;
}

void SkeletonPoseTool::hovered(QPointF)
{
}

void SkeletonPoseTool::left()
{
}

QString SkeletonPoseTool::mouseHelp() const
{
    return tr("Click near a bone: select it · Drag from a bone: turn it about its head · Drag elsewhere: orbit · "
              "Right/middle drag: pan · Wheel: zoom");
}

} // namespace trimlab::ui
