#pragma once
/// \file
/// Posing with the mouse (a ViewportTool, like the brush): a left press within
/// kPickPixels of a bone of the overlay selects it (boneSelected) and starts a drag that
/// turns it about its head in the view plane — the angle the cursor sweeps around the
/// projected head, about the view direction (rotateRequested, world axis, radians, one
/// signal per mouse move). A press away from every bone, or with a modifier, or with
/// another button, is left to the camera.

#include "ui/viewport/viewport_tool.h"

#include <QObject>
#include <QPointF>

#include <glm/vec3.hpp>

namespace trimlab::ui {

class SkeletonOverlay;
class ViewportWidget;

class SkeletonPoseTool : public QObject, public ViewportTool {
    Q_OBJECT
public:
    static constexpr double kPickPixels = 8.0;

    SkeletonPoseTool(ViewportWidget* viewport, SkeletonOverlay* overlay, QObject* parent = nullptr);

    [[nodiscard]] bool isDragging() const { return m_bone >= 0; }

    bool pressed(QMouseEvent& event) override;
    void moved(QMouseEvent& event) override;
    void released(QMouseEvent& event) override;
    void hovered(QPointF position) override;
    void left() override;
    [[nodiscard]] QString mouseHelp() const override;

signals:
    void boneSelected(int bone);
    /// Turn `bone` by `radians` about the world `axis` (through its posed head).
    void rotateRequested(int bone, const glm::dvec3& axis, double radians);

private:
    ViewportWidget* m_viewport;
    SkeletonOverlay* m_overlay;
    int m_bone = -1;
    QPointF m_head;
    double m_lastAngle = 0.0;
};

} // namespace trimlab::ui
