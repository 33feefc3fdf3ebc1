#pragma once
/// \file
/// The base of the drawings over the 3D view (the rig, the control net): a transparent
/// child widget of the ViewportWidget that covers it, follows its size, takes no mouse
/// events (tools do the picking) and repaints after every frame the viewport renders, so
/// what it draws follows orbit, pan and zoom. Starts hidden.

#include <QPointF>
#include <QWidget>

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace trimlab::ui {

class ViewportWidget;

class ViewportOverlay : public QWidget {
    Q_OBJECT
public:
    /// Becomes a child of `viewport`, covering it; `objectName` names it for tests.
    ViewportOverlay(ViewportWidget* viewport, const QString& objectName);

    /// `points` (world space) in widget pixels through the viewport's current camera;
    /// nullopt for points behind the eye.
    [[nodiscard]] std::vector<std::optional<QPointF>> projectToViewport(const std::vector<glm::dvec3>& points) const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    ViewportWidget* m_viewport;
};

} // namespace trimlab::ui
