#pragma once
/// \file
/// Qt's widget geometry as the glm vectors core takes: core computes without Qt, so
/// the widgets convert positions and sizes where they hand them over.

#include <glm/vec2.hpp>

#include <QPointF>
#include <QSize>

#include <optional>
#include <vector>

namespace trimlab::ui {

[[nodiscard]] inline glm::dvec2 toGlm(QPointF point)
{
    return {point.x(), point.y()};
}

/// x: width, y: height.
[[nodiscard]] inline glm::ivec2 toGlm(QSize size)
{
    return {size.width(), size.height()};
}

[[nodiscard]] inline std::vector<std::optional<glm::dvec2>> toGlm(const std::vector<std::optional<QPointF>>& points)
{
    std::vector<std::optional<glm::dvec2>> converted;
    converted.reserve(points.size());
    for (const std::optional<QPointF>& point : points)
        converted.push_back(point ? std::optional(toGlm(*point)) : std::nullopt);
    return converted;
}

} // namespace trimlab::ui
