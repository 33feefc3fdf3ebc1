#include "ui/skeleton/skeleton_overlay.h"

#include "ui/viewport/viewport_widget.h"

#include <QPainter>
#include <QPen>

#include <glm/vec4.hpp>

namespace trimlab::ui {

namespace {

const QColor kSelectedColor(255, 200, 0);

} // namespace

SkeletonOverlay::SkeletonOverlay(ViewportWidget* viewport)
    : ViewportOverlay(viewport, QStringLiteral("skeletonOverlay"))
{
}

void SkeletonOverlay::setSkeleton(std::vector<glm::dvec3> joints, std::vector<std::array<int, 2>> bones, int root,
                                  const glm::dmat4& model)
{
    for (glm::dvec3& joint : joints)
        joint = glm::dvec3(model * glm::dvec4(joint, 1.0));
    m_joints = std::move(joints);
    m_bones = std::move(bones);
    m_root = root;
    if (m_selected >= int(m_bones.size()))
        m_selected = -1;
    setVisible(!m_joints.empty());
    update();
}

void SkeletonOverlay::setSelectedBone(int bone)
{
    m_selected = bone >= 0 && bone < int(m_bones.size()) ? bone : -1;
    update();
}

std::vector<std::optional<QPointF>> SkeletonOverlay::projectedJoints() const
{
    return projectToViewport(m_joints);
}

void SkeletonOverlay::paintEvent(QPaintEvent*)
{
    if (m_joints.empty())
        return;
    const std::vector<std::optional<QPointF>> points = projectedJoints();
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    auto drawBone = [&](std::size_t i, bool selected) {
        const auto& head = points[std::size_t(m_bones[i][0])];
        const auto& tail = points[std::size_t(m_bones[i][1])];
        if (!head || !tail)
            return;
        // A dark outline under a light line stays visible on any surface colour.
        painter.setPen(QPen(QColor(20, 20, 20, 200), selected ? 7.0 : 4.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(*head, *tail);
        painter.setPen(
            QPen(selected ? kSelectedColor : QColor(240, 240, 240), selected ? 4.0 : 2.0, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(*head, *tail);
    };
    for (std::size_t i = 0; i < m_bones.size(); ++i)
        if (int(i) != m_selected)
            drawBone(i, false);
    painter.setPen(QPen(QColor(20, 20, 20), 1.0));
    for (std::size_t j = 0; j < points.size(); ++j) {
        if (!points[j])
            continue;
        painter.setBrush(QColor(80, 200, 255));
        painter.drawEllipse(*points[j], 3.5, 3.5);
        if (int(j) == m_root) {
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(*points[j], 7.0, 7.0);
        }
    }
    // The selected bone last: short bones would otherwise hide under their joints' dots.
    if (m_selected >= 0)
        drawBone(std::size_t(m_selected), true);
}

} // namespace trimlab::ui
