// The main window as a first-time user sees it, at 1100×720 (the default size) and at
// 1600×1000: every dock tab shows its whole title, the Render panel scrolls only
// vertically, the status bar's message fits, and the first scene is shown whole (no
// clipping plane cuts it on first start). Screenshots of both sizes go to the test
// output folder (the ones in docs/ are copies of them).
#include "gl_test_context.h"
#include "named_child.h"
#include "shown_main_window.h"
#include "test_paths.h"
#include "widget_test_main.h"

#include "ui/render_panel/render_panel.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/window/main_window.h"
#include "ui/viewport/viewport_widget.h"

#include <QDockWidget>
#include <QScrollArea>
#include <QStyle>
#include <QScrollBar>
#include <QSlider>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

constexpr int kWaitMs = 30000;

/// "tab text" for every visible dock tab whose rectangle is narrower than its text.
QStringList truncatedTabs(const QMainWindow& window)
{
    QStringList truncated;
    for (const QTabBar* bar : window.findChildren<QTabBar*>()) {
        if (!bar->isVisible())
            continue;
        const bool vertical = bar->shape() == QTabBar::RoundedWest || bar->shape() == QTabBar::RoundedEast ||
                              bar->shape() == QTabBar::TriangularWest || bar->shape() == QTabBar::TriangularEast;
        for (int i = 0; i < bar->count(); ++i) {
            const QRect rect = bar->tabRect(i);
            const int room = vertical ? rect.height() : rect.width();
            // The style's padding around a tab's text, as QTabBar sizes a tab it need not elide.
            const int needed = bar->fontMetrics().horizontalAdvance(bar->tabText(i)) +
                               bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar);
            if (room < needed)
                truncated << QStringLiteral("%1 (%2 of %3 px)").arg(bar->tabText(i)).arg(room).arg(needed);
        }
    }
    return truncated;
}

} // namespace

class TestWindowLayout : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void firstStartFitsTheWindow_data();
    void firstStartFitsTheWindow();

private:
    QTemporaryDir m_dir;
};

void TestWindowLayout::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

void TestWindowLayout::firstStartFitsTheWindow_data()
{
    QTest::addColumn<QSize>("size");
    QTest::newRow("1100x720") << QSize(1100, 720);
    QTest::newRow("1600x1000") << QSize(1600, 1000);
}

void TestWindowLayout::firstStartFitsTheWindow()
{
    QFETCH(QSize, size);
    const QString name = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
    auto window = test::showMainWindow(m_dir.filePath(name + QStringLiteral(".ini")), QSize());
    window->resize(size);
    QVERIFY(QTest::qWaitFor([&] { return window->scene() && !window->isLoading() && window->viewport()->lastFrame(); },
                            kWaitMs));
    QTest::qWait(300); // the docks' layouts and the status bar settle
    const QString shot =
        QString::fromStdString((test::outputDir() / ("main-window-" + name + ".png").toStdString()).string());
    QVERIFY(window->grab().save(shot));
    qInfo("screenshot: %s", qPrintable(shot));

    const QStringList truncated = truncatedTabs(*window);
    QVERIFY2(truncated.isEmpty(), qPrintable(truncated.join(QStringLiteral(", "))));
    auto* render = window->findChild<QDockWidget*>(QStringLiteral("renderDock"));
    QVERIFY(render);
    for (const QScrollArea* area : render->findChildren<QScrollArea*>())
        QVERIFY2(!area->horizontalScrollBar()->isVisible(), "the Render panel scrolls sideways");
    // No side panel scrolls sideways: a field focused at the edge would move under the
    // cursor. Each is raised in turn, as a click on its tab does.
    for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
        auto* area = qobject_cast<QScrollArea*>(dock->widget());
        if (!area || window->dockWidgetArea(dock) != Qt::RightDockWidgetArea)
            continue;
        dock->raise();
        QTest::qWait(100);
        if (!dock->isVisible()) // the animation panels, while a mesh is shown
            continue;
        qInfo("%s: content %d px wide at least, %d px shown", qPrintable(dock->objectName()),
              area->widget()->minimumSizeHint().width(), area->viewport()->width());
        QStringList wide; // what does not fit, to say where to look
        for (const QWidget* w : area->widget()->findChildren<QWidget*>())
            if (w->isVisible() && w->minimumSizeHint().width() > area->viewport()->width() - 40)
                wide << QStringLiteral("%1 '%2' %3 px")
                            .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName())
                            .arg(w->minimumSizeHint().width());
        QVERIFY2(!area->horizontalScrollBar()->isVisible(),
                 qPrintable(dock->objectName() + QStringLiteral(" scrolls sideways: ") + wide.join(", ")));
    }
    render->raise();
    // The clip offset slider gets most of its row (it had 80 pixels to sweep the model).
    auto* slider = render->findChild<QSlider*>(QStringLiteral("clipOffsetSlider"));
    QVERIFY(slider);
    qInfo("clip offset slider: %d px of a %d px row", slider->width(), slider->parentWidget()->width());
    QVERIFY2(slider->width() * 2 >= slider->parentWidget()->width(), qPrintable(QString::number(slider->width())));
    // The first scene is shown whole: no clipping plane on first start.
    QVERIFY(!window->viewport()->lastFrame()->settings.clipSet().anyEnabled());
    const QString message = window->statusBar()->currentMessage();
    QVERIFY2(window->statusBar()->fontMetrics().horizontalAdvance(message) < window->statusBar()->width() / 2,
             qPrintable(message));
}

TRIMLAB_WIDGET_TEST_MAIN(TestWindowLayout)
#include "tst_window_layout.moc"
