#pragma once
/// \file
/// The control net (NURBS) or cage (subdivision) drawn over the 3D view (thesis 8.2: the
/// designer edits the surface through these points): a transparent child widget of the
/// ViewportWidget, painted with QPainter over the GL frame like SkeletonOverlay — net
/// edges as thin lines, control points as dots, selected points larger and in a highlight
/// colour, the hovered point ringed. Points are projected with the viewport's current
/// camera (ui/viewport/widget_projection.h) and repainted after every frame the viewport renders, so
/// the net follows orbit, pan and zoom. It takes no mouse events (control_point_tool.h
/// picks through projectedPoints()).

#include "ui/viewport/viewport_overlay.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <QRectF>

#include <optional>
#include <vector>

namespace trimlab::ui {

class ViewportWidget;

class ControlNetOverlay : public ViewportOverlay {
    Q_OBJECT
public:
    /// Becomes a child of `viewport`, covering it, and follows its size and frames.
    /// Hidden until setNet() gives it points and the net is shown.
    explicit ControlNetOverlay(ViewportWidget* viewport);

    /// Control points in object space (#C), transformed by `model` into world space; net
    /// edges as index pairs into them (pairs with an index >= #C are not drawn). Keeps
    /// the selection where its indices are still valid. Empty points: nothing is drawn.
    void setNet(const std::vector<glm::dvec3>& points, std::vector<std::array<std::uint32_t, 2>> edges,
                const glm::dmat4& model);
    /// Moves the points only (same count as setNet's; a drag preview, undo, redo).
    /// A count mismatch is ignored (the next setNet() brings the right points).
    void setPoints(const std::vector<glm::dvec3>& points);
    void clearNet();
    /// Whether the net is drawn at all ("Show control net"); hidden also without points.
    void setNetShown(bool shown);
    [[nodiscard]] bool netShown() const { return m_shown; }

    /// Selected control points (ascending, unique; indices >= #C are dropped).
    void setSelection(std::vector<std::uint32_t> selection);
    [[nodiscard]] const std::vector<std::uint32_t>& selection() const { return m_selection; }
    /// The ringed point (nullopt: none).
    void setHovered(std::optional<std::uint32_t> point);
    [[nodiscard]] std::optional<std::uint32_t> hovered() const { return m_hovered; }
    /// The box being dragged out to select points (widget coordinates); nullopt: none.
    void setSelectionBox(std::optional<QRectF> box);

    [[nodiscard]] std::size_t pointCount() const { return m_points.size(); }
    [[nodiscard]] std::size_t edgeCount() const { return m_edges.size(); }
    /// The points in logical widget coordinates with the viewport's current camera
    /// (nullopt: behind the eye).
    [[nodiscard]] std::vector<std::optional<QPointF>> projectedPoints() const;
    /// World-space position of point `index` (no range check).
    [[nodiscard]] const glm::dvec3& worldPoint(std::size_t index) const { return m_points[index]; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    void updateVisibility();
    std::optional<QRectF> m_box;

    glm::dmat4 m_model{1.0};
    std::vector<glm::dvec3> m_points; ///< world space
    std::vector<std::array<std::uint32_t, 2>> m_edges;
    std::vector<std::uint32_t> m_selection;
    std::optional<std::uint32_t> m_hovered;
    bool m_shown = true;
};

} // namespace trimlab::ui
