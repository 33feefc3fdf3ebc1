#pragma once
/// \file
/// The orientation gizmo in the view's lower-left corner, as in Blender and MeshLab: the
/// world's x (red), y (green) and z (blue) axes turned like the scene, labelled, the
/// ones pointing away drawn first and fainter. It follows orbiting (it repaints with every
/// frame) and ignores pan and zoom.

#include "ui/viewport/viewport_overlay.h"

#include <array>

namespace trimlab::ui {

class OrientationAxes : public ViewportOverlay {
    Q_OBJECT
public:
    explicit OrientationAxes(ViewportWidget* viewport);

    /// The gizmo's centre in widget pixels.
    [[nodiscard]] QPointF centre() const;
    /// Where the x, y and z axes end on screen for the viewport's current camera.
    [[nodiscard]] std::array<QPointF, 3> axisEnds() const;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    ViewportWidget* m_viewport;
};

} // namespace trimlab::ui
