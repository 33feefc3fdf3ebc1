#include "ui/viewport/orientation_axes.h"

#include "ui/viewport/viewport_widget.h"

#include <QPainter>

#include <glm/geometric.hpp>

#include <algorithm>
#include <numeric>

namespace trimlab::ui {

namespace {

constexpr double kAxisPixels = 28.0;
constexpr double kMarginPixels = 42.0;

const std::array<glm::dvec3, 3> kAxes = {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0),
                                         glm::dvec3(0.0, 0.0, 1.0)};
const std::array<QColor, 3> kColours = {QColor(230, 70, 70), QColor(90, 200, 90), QColor(80, 140, 240)};
const std::array<const char*, 3> kLabels = {"X", "Y", "Z"};

/// The camera's right, up and forward directions (orthonormal).
std::array<glm::dvec3, 3> viewBasis(const Camera& camera)
{
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    return {right, glm::cross(right, forward), forward};
}

} // namespace

OrientationAxes::OrientationAxes(ViewportWidget* viewport)
    : ViewportOverlay(viewport, QStringLiteral("orientationAxes")), m_viewport(viewport)
{
}

QPointF OrientationAxes::centre() const
{
    return {kMarginPixels, double(height()) - kMarginPixels};
}

std::array<QPointF, 3> OrientationAxes::axisEnds() const
{
    const auto [right, up, forward] = viewBasis(m_viewport->camera());
    std::array<QPointF, 3> ends;
    for (std::size_t a = 0; a < 3; ++a) // widget y points down
        ends[a] = centre() + kAxisPixels * QPointF(glm::dot(kAxes[a], right), -glm::dot(kAxes[a], up));
    return ends;
}

void OrientationAxes::paintEvent(QPaintEvent*)
{
    const glm::dvec3 forward = viewBasis(m_viewport->camera())[2];
    const std::array<QPointF, 3> ends = axisEnds();
    std::array<std::size_t, 3> order{};
    std::iota(order.begin(), order.end(), std::size_t(0));
    // Farthest first, so the axes pointing at the viewer are drawn over the others.
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return glm::dot(kAxes[a], forward) > glm::dot(kAxes[b], forward); });
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setBold(true);
    painter.setFont(font);
    for (const std::size_t a : order) {
        QColor colour = kColours[a];
        if (glm::dot(kAxes[a], forward) > 0.0)
            colour.setAlpha(140); // points away from the viewer
        painter.setPen(QPen(colour, 2.5, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(centre(), ends[a]);
        const QPointF along = ends[a] - centre();
        const double length = std::max(1.0, std::hypot(along.x(), along.y()));
        const QPointF label = ends[a] + along / length * 8.0 - QPointF(4.0, -5.0);
        painter.drawText(label, QLatin1String(kLabels[a]));
    }
}

} // namespace trimlab::ui
