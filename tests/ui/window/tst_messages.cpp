// View ▸ Messages in the real main window: every status line and message box is kept with
// its time, whole — the status bar cuts a long line at the window's width and replaces it
// with the next — and a click on the status bar opens the dock. A failed open is there as
// an error naming the file; Clear empties it. The log keeps at most kMaxEntries.
#include "demo_window.h"
#include "gl_test_context.h"
#include "message_box_closer.h"
#include "named_child.h"
#include "widget_test_main.h"

#include "ui/common/message_log.h"
#include "ui/window/main_window.h"
#include "ui/window/messages_panel.h"

#include <QDockWidget>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

class TestMessages : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyMessageIsKeptWhole();
    void theLogKeepsTheNewest();

private:
    QTemporaryDir m_dir;
};

void TestMessages::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

void TestMessages::everyMessageIsKeptWhole()
{
    auto window = test::showDemoWindow(m_dir.filePath(QStringLiteral("messages.ini")), QSize(256, 192));
    QVERIFY(window->scene());
    QDockWidget* dock = window->messagesDock();
    QVERIFY(!dock->isVisible());
    auto* panel = test::child<MessagesPanel>(window.get(), "messagesPanel");
    // The demo's status line ("pushed-sphere: N triangles") is the newest, whole.
    QVERIFY2(!panel->lines().isEmpty() && panel->lines().back().contains(QStringLiteral("pushed-sphere: ")),
             qPrintable(panel->lines().join(QLatin1Char('\n'))));

    test::MessageBoxCloser closer;
    const QString missing = m_dir.filePath(QStringLiteral("no-such-mesh.obj"));
    QSignalSpy failed(window.get(), &MainWindow::sceneLoadFailed);
    window->openSource(missing);
    QVERIFY(failed.wait(test::kDemoWaitMs));
    const MessageLog::Entry& error = window->messageLog()->entries().back();
    QCOMPARE(error.kind, MessageLog::Kind::Error);
    QVERIFY2(error.text.contains(QStringLiteral("no-such-mesh.obj")), qPrintable(error.text));
    QVERIFY2(panel->lines().back().contains(QStringLiteral("Error  Could not open")),
             qPrintable(panel->lines().back()));

    // A line far wider than the window stays whole in the log.
    const QString longLine = QStringLiteral("a long status line ") + QString(400, QLatin1Char('x'));
    window->messageLog()->add(MessageLog::Kind::Status, longLine);
    QVERIFY(panel->lines().back().endsWith(longLine));

    QTest::mouseClick(window->statusBar(), Qt::LeftButton);
    QVERIFY(QTest::qWaitFor([&] { return dock->isVisible(); }, 5000));
    QTest::mouseClick(test::child<QPushButton>(panel, "clearMessagesButton"), Qt::LeftButton);
    QVERIFY(panel->lines().isEmpty() && window->messageLog()->entries().empty());
}

void TestMessages::theLogKeepsTheNewest()
{
    MessageLog log;
    QSignalSpy added(&log, &MessageLog::added);
    log.add(MessageLog::Kind::Status, QStringLiteral("   ")); // nothing to keep
    QCOMPARE(added.count(), 0);
    for (std::size_t i = 0; i < MessageLog::kMaxEntries + 5; ++i)
        log.add(MessageLog::Kind::Status, QString::number(i));
    QCOMPARE(log.entries().size(), MessageLog::kMaxEntries);
    QCOMPARE(log.entries().front().text, QStringLiteral("5"));
    MessagesPanel panel(log);
    QCOMPARE(panel.lines().size(), qsizetype(MessageLog::kMaxEntries));
    log.add(MessageLog::Kind::Warning, QStringLiteral("newest"));
    QCOMPARE(panel.lines().size(), qsizetype(MessageLog::kMaxEntries));
    QVERIFY(panel.lines().back().endsWith(QStringLiteral("Warning  newest")));
}

TRIMLAB_WIDGET_TEST_MAIN(TestMessages)
#include "tst_messages.moc"
