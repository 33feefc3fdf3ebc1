#include "ui/window/dock_tab_bars.h"

#include <QChildEvent>
#include <QEvent>
#include <QMainWindow>
#include <QTabBar>

namespace trimlab::ui {

namespace {

void showWholeTitles(QTabBar& bar)
{
    bar.setElideMode(Qt::ElideNone);
    bar.setUsesScrollButtons(true);
}

/// Sets every tab bar the main window adds as its child (a dock area's tabs).
class DockTabBarWatcher : public QObject {
public:
    explicit DockTabBarWatcher(QMainWindow& window) : QObject(&window)
    {
        for (QTabBar* bar : window.findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
            showWholeTitles(*bar);
        window.installEventFilter(this);
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        // ChildPolished comes after the layout configured the new bar (it sets eliding).
        if (event->type() == QEvent::ChildPolished) {
            if (auto* bar = qobject_cast<QTabBar*>(static_cast<QChildEvent*>(event)->child()))
                showWholeTitles(*bar);
        }
        return QObject::eventFilter(watched, event);
    }
};

} // namespace

void keepDockTabTitlesWhole(QMainWindow& window)
{
    new DockTabBarWatcher(window);
}

} // namespace trimlab::ui
