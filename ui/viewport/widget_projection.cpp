#include "ui/viewport/widget_projection.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace trimlab::ui {

std::optional<QPointF> projectToWidget(const Camera& camera, QSizeF size, const glm::dvec3& world)
{
    if (size.width() <= 0.0 || size.height() <= 0.0 || !std::isfinite(world.x) || !std::isfinite(world.y) ||
        !std::isfinite(world.z))
        return std::nullopt;
    const double aspect = size.width() / size.height();
    const glm::dvec4 clip = projectionMatrix(camera, aspect) * viewMatrix(camera) * glm::dvec4(world, 1.0);
    if (!(clip.w > 0.0))
        return std::nullopt;
    const double x = clip.x / clip.w;
    const double y = clip.y / clip.w;
    // NDC y points up, widget y down.
    return QPointF((x + 1.0) * 0.5 * size.width(), (1.0 - y) * 0.5 * size.height());
}

double distanceToSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double length2 = QPointF::dotProduct(ab, ab);
    double t = length2 > 0.0 ? QPointF::dotProduct(p - a, ab) / length2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const QPointF d = p - (a + t * ab);
    return std::hypot(d.x(), d.y());
}

int nearestSegment(QPointF cursor, std::span<const std::optional<QPointF>> points,
                   std::span<const std::array<int, 2>> bones, double maxDistance)
{
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < bones.size(); ++i) {
        const auto [head, tail] = bones[i];
        if (head < 0 || tail < 0 || std::size_t(head) >= points.size() || std::size_t(tail) >= points.size() ||
            !points[std::size_t(head)] || !points[std::size_t(tail)])
            continue;
        const double d = distanceToSegment(cursor, *points[std::size_t(head)], *points[std::size_t(tail)]);
        if (d <= maxDistance && d < bestDistance) {
            best = int(i);
            bestDistance = d;
        }
    }
    return best;
}

} // namespace trimlab::ui
