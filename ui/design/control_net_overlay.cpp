#include "ui/design/control_net_overlay.h"

#include "ui/viewport/viewport_widget.h"

#include <QPainter>
#include <QPen>

#include <glm/vec4.hpp>

#include <algorithm>

namespace trimlab::ui {

namespace {

const QColor kEdgeColor(235, 235, 235, 210);
const QColor kOutlineColor(20, 20, 20, 200);
const QColor kPointColor(80, 200, 255);
const QColor kSelectedColor(255, 200, 0);

} // namespace

ControlNetOverlay::ControlNetOverlay(ViewportWidget* viewport)
    : ViewportOverlay(viewport, QStringLiteral("controlNetOverlay"))
{
}

void ControlNetOverlay::setNet(const std::vector<glm::dvec3>& points, std::vector<std::array<std::uint32_t, 2>> edges,
                               const glm::dmat4& model)
{
    m_model = model;
    m_edges = std::move(edges);
    m_points.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        m_points[i] = glm::dvec3(model * glm::dvec4(points[i], 1.0));
    std::erase_if(m_selection, [&](std::uint32_t i) { return i >= m_points.size(); });
    if (m_hovered && *m_hovered >= m_points.size())
        m_hovered.reset();
    updateVisibility();
    update();
}

void ControlNetOverlay::setPoints(const std::vector<glm::dvec3>& points)
{
    if (points.size() != m_points.size())
        return;
    for (std::size_t i = 0; i < points.size(); ++i)
        m_points[i] = glm::dvec3(m_model * glm::dvec4(points[i], 1.0));
    update();
}

void ControlNetOverlay::clearNet()
{
    m_points.clear();
    m_edges.clear();
    m_selection.clear();
    m_hovered.reset();
    updateVisibility();
}

void ControlNetOverlay::setNetShown(bool shown)
{
    m_shown = shown;
    updateVisibility();
}

void ControlNetOverlay::setSelection(std::vector<std::uint32_t> selection)
{
    std::sort(selection.begin(), selection.end());
    selection.erase(std::unique(selection.begin(), selection.end()), selection.end());
    std::erase_if(selection, [&](std::uint32_t i) { return i >= m_points.size(); });
    m_selection = std::move(selection);
    update();
}

void ControlNetOverlay::setHovered(std::optional<std::uint32_t> point)
{
    if (point && *point >= m_points.size())
        point.reset();
    if (point == m_hovered)
        return;
    m_hovered = point;
    update();
}

std::vector<std::optional<QPointF>> ControlNetOverlay::projectedPoints() const
{
    return projectToViewport(m_points);
}

void ControlNetOverlay::updateVisibility()
{
    const bool visible = m_shown && !m_points.empty();
    setVisible(visible);
    if (visible)
        raise();
}

void ControlNetOverlay::paintEvent(QPaintEvent*)
{
    if (m_points.empty())
        return;
    const std::vector<std::optional<QPointF>> points = projectedPoints();
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    // A dark outline under a light line stays visible on the yellow and blue trim colours.
    for (const auto& [width, color] : {std::pair{3.0, kOutlineColor}, std::pair{1.2, kEdgeColor}}) {
        painter.setPen(QPen(color, width, Qt::SolidLine, Qt::RoundCap));
        for (const auto& [a, b] : m_edges) {
            if (a < points.size() && b < points.size() && points[a] && points[b])
                painter.drawLine(*points[a], *points[b]);
        }
    }
    painter.setPen(QPen(QColor(20, 20, 20), 1.0));
    painter.setBrush(kPointColor);
    for (const auto& p : points)
        if (p)
            painter.drawEllipse(*p, 3.0, 3.0);
    painter.setBrush(kSelectedColor);
    for (std::uint32_t i : m_selection)
        if (points[i])
            painter.drawEllipse(*points[i], 4.5, 4.5);
    if (m_hovered && points[*m_hovered]) {
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(QColor(255, 255, 255), 1.5));
        painter.drawEllipse(*points[*m_hovered], 8.0, 8.0);
    }
    if (m_box) {
        painter.setBrush(QColor(255, 255, 255, 40));
        painter.setPen(QPen(QColor(255, 255, 255), 1.0, Qt::DashLine));
        painter.drawRect(*m_box);
    }
}

void ControlNetOverlay::setSelectionBox(std::optional<QRectF> box)
{
    m_box = box;
    update();
}

} // namespace trimlab::ui
