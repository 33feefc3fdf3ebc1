// Without any OpenGL the main window still starts: the 3D view is replaced by a text
// that says why, a dialog says it too, and everything else (loading, the panel, the
// menus) keeps working. Forces the situation by starting on Qt's offscreen platform
// without an X display, where no OpenGL context can be created (docs/llvmpipe-notes.md).
#include "message_box_closer.h"

#include "ui/window/main_window.h"
#include "ui/render_panel/render_workspace.h"
#include "ui/render_panel/render_panel.h"
#include "ui/viewport/viewport_widget.h"

#include <QLabel>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

class TestMainWindowWithoutGl : public QObject {
    Q_OBJECT
private slots:
    void explainsAndKeepsWorking();
};

void TestMainWindowWithoutGl::explainsAndKeepsWorking()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    test::MessageBoxCloser closer;
    MainWindow window(dir.filePath(QStringLiteral("settings.ini")));
    window.show();
    QVERIFY(QTest::qWaitFor([&] { return window.scene() != nullptr; }, 20000));
    QCOMPARE(QString::fromStdString(window.scene()->source), MainWindow::defaultSource());

    QVERIFY(window.findChildren<ViewportWidget*>().isEmpty()); // no QOpenGLWidget in the window
    auto* label = window.findChild<QLabel*>(QStringLiteral("viewportUnavailableLabel"));
    QVERIFY(label && label->isVisible());
    QVERIFY2(label->text().contains(QStringLiteral("OpenGL")), qPrintable(label->text()));
    QVERIFY(!window.viewport()->errorMessage().isEmpty());
    QVERIFY(QTest::qWaitFor([&] { return !closer.seen().isEmpty(); }, 5000));
    QVERIFY2(closer.seen().front().contains(QStringLiteral("OpenGL")), qPrintable(closer.seen().front()));

    QString error;
    QVERIFY(!window.exportImage(dir.filePath(QStringLiteral("x.png")), &error));
    QVERIFY(!error.isEmpty());
    QVERIFY(window.renderWorkspace()->panel()->isEnabled());
    QTest::qWait(200); // repaints of the window must not crash
}

int main(int argc, char** argv)
{
    qunsetenv("DISPLAY");
    qunsetenv("WAYLAND_DISPLAY");
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    TestMainWindowWithoutGl test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_main_window_without_gl.moc"
