#include "ui/common/panel_wheel_guard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>

namespace trimlab::ui {

namespace {

/// Marks the scroll areas whose controls the filter guards.
constexpr const char* kGuardedPanel = "trimlabGuardedPanel";

bool isValueControl(const QObject* object)
{
    return qobject_cast<const QAbstractSpinBox*>(object) || qobject_cast<const QComboBox*>(object) ||
           qobject_cast<const QAbstractSlider*>(object);
}

/// The guarded panel `widget` lies in, or nullptr.
QScrollArea* guardedPanelOf(QWidget* widget)
{
    for (QWidget* parent = widget->parentWidget(); parent; parent = parent->parentWidget())
        if (auto* area = qobject_cast<QScrollArea*>(parent); area && area->property(kGuardedPanel).toBool())
            return area;
    return nullptr;
}

class PanelWheelFilter : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (event->type() != QEvent::Wheel || !isValueControl(watched))
            return false;
        auto* control = static_cast<QWidget*>(watched);
        // A scroll bar is a slider too: it scrolls, which is what the wheel should do.
        if (control->hasFocus() || qobject_cast<QScrollBar*>(control))
            return false;
        QScrollArea* panel = guardedPanelOf(control);
        if (!panel)
            return false;
        QCoreApplication::sendEvent(panel->verticalScrollBar(), event);
        return true; // the control keeps its value
    }
};

} // namespace

void guardPanelWheel(QScrollArea& panel)
{
    static PanelWheelFilter* filter = nullptr;
    if (!filter) {
        filter = new PanelWheelFilter(qApp);
        qApp->installEventFilter(filter);
    }
    panel.setProperty(kGuardedPanel, true);
    for (QWidget* child : panel.findChildren<QWidget*>())
        if (isValueControl(child) && child->focusPolicy() == Qt::WheelFocus)
            child->setFocusPolicy(Qt::StrongFocus);
}

} // namespace trimlab::ui
