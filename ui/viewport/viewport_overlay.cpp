#include "ui/viewport/viewport_overlay.h"

#include "ui/viewport/widget_projection.h"
#include "ui/viewport/viewport_widget.h"

#include <QEvent>

namespace trimlab::ui {

ViewportOverlay::ViewportOverlay(ViewportWidget* viewport, const QString& objectName)
    : QWidget(viewport), m_viewport(viewport)
{
    setObjectName(objectName);
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
    setGeometry(viewport->rect());
    viewport->installEventFilter(this);
    connect(viewport, &ViewportWidget::frameRendered, this, qOverload<>(&QWidget::update));
    hide();
}

std::vector<std::optional<QPointF>> ViewportOverlay::projectToViewport(const std::vector<glm::dvec3>& points) const
{
    const Camera camera = m_viewport->camera();
    const QSizeF size = m_viewport->size();
    std::vector<std::optional<QPointF>> projected;
    projected.reserve(points.size());
    for (const glm::dvec3& p : points)
        projected.push_back(projectToWidget(camera, size, p));
    return projected;
}

bool ViewportOverlay::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_viewport && event->type() == QEvent::Resize) {
        setGeometry(m_viewport->rect());
        raise();
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace trimlab::ui
