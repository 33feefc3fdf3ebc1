// Autosave and crash recovery in the real main window (ui/design/autosave.h,
// ui/design/session_recovery.h): a modified design session is autosaved into the recovery folder
// and the copy disappears once the work is saved; the work of a TrimLab that died (its
// autosave without a live lock) is offered at the next start, and Recover brings the
// history back under its own project path, modified; Discard deletes the copy; the
// autosave of a TrimLab that is still running is never offered.
#include "design_window.h"
#include "gl_test_context.h"

#include "ui/common/document.h"
#include "ui/design/autosave.h"
#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/window/main_window.h"
#include "ui/design/project_files.h"
#include "ui/design/session_recovery.h"
#include "core/scene/shape_generators.h"
#include "core/timeline/project_file.h"

#include <QAbstractButton>
#include <QFile>
#include <QLockFile>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

constexpr QSize kViewportSize(96, 72);

// A history of two sets on a small sphere (what a crashed TrimLab left behind).
timeline::Timeline crashedHistory()
{
    timeline::Timeline history(makeIcosphere(glm::dvec3(0.0), 1.0, 2), DynamicRule::Confluent);
    history.startSet(DynamicRule::ConstructiveAdditive);
    return history;
}

QAbstractButton* buttonWithRole(QMessageBox* box, QMessageBox::ButtonRole role)
{
    for (QAbstractButton* button : box->buttons())
        if (box->buttonRole(button) == role)
            return button;
    return nullptr;
}

} // namespace

class TestSessionRecovery : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void autosaveWritesModifiedWorkAndClearsWhenSaved();
    void recoverBringsBackTheHistoryModified();
    void anUntitledRecoveryShowsNoInternalName();
    void discardDeletesTheAutosave();
    void liveSessionsAreNeverOffered();

private:
    [[nodiscard]] QString path(const QString& name) const { return m_dir.filePath(name); }
    // A main window whose recovery folder is `recovery` and whose timer is off (the test
    // calls saveNow()).
    [[nodiscard]] std::unique_ptr<MainWindow> showWindow(const QString& name, const QString& recovery)
    {
        const QString ini = path(name + QStringLiteral(".ini"));
        {
            QSettings settings(ini, QSettings::IniFormat);
            settings.setValue(QStringLiteral("recovery/directory"), recovery);
            settings.setValue(QStringLiteral("recovery/intervalMinutes"), 0);
        }
        return test::showDesignWindow(ini, kViewportSize);
    }
    // Leaves what a killed TrimLab leaves: its autosave and info, no live lock.
    void writeCrashedSession(const QString& recovery, const QString& stem, const QString& originalPath)
    {
        QVERIFY(QDir().mkpath(recovery));
        timeline::saveProject(crashedHistory(),
                              (recovery + QLatin1Char('/') + stem + QStringLiteral(".trimlab")).toStdString());
        QFile info(recovery + QLatin1Char('/') + stem + QStringLiteral(".json"));
        QVERIFY(info.open(QIODevice::WriteOnly));
        info.write(QStringLiteral(R"({"projectPath": "%1", "savedAt": "2026-11-20T10:00:00.000Z"})")
                       .arg(originalPath)
                       .toUtf8());
    }
    static QMessageBox* waitForOffer(MainWindow& window)
    {
        QMessageBox* box = nullptr;
        const bool shown = QTest::qWaitFor(
            [&] {
                box = window.findChild<QMessageBox*>(QStringLiteral("recoveryOffer"));
                return box && box->isVisible();
            },
            test::kWaitMs);
        return shown ? box : nullptr;
    }
    // Presses Recover on `box` and waits until the crashed history is shown.
    static bool recoverAndWait(MainWindow& window, QMessageBox* box)
    {
        QAbstractButton* recoverButton = box ? buttonWithRole(box, QMessageBox::AcceptRole) : nullptr;
        if (!recoverButton)
            return false;
        recoverButton->click();
        const timeline::Timeline expected = crashedHistory();
        return QTest::qWaitFor(
            [&] {
                const DesignSession* session = window.designWorkspace()->session();
                return !window.isLoading() && session && session->timeline() == expected;
            },
            test::kWaitMs);
    }
    static bool waitForDefaultScene(MainWindow& window)
    {
        return QTest::qWaitFor([&] { return !window.isLoading() && window.designWorkspace()->session(); },
                               test::kWaitMs);
    }

    QTemporaryDir m_dir;
};

void TestSessionRecovery::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

void TestSessionRecovery::autosaveWritesModifiedWorkAndClearsWhenSaved()
{
    const QString recovery = path(QStringLiteral("autosave-recovery"));
    auto window = showWindow(QStringLiteral("autosave"), recovery);
    QVERIFY(waitForDefaultScene(*window));
    Autosave& autosave = window->designWorkspace()->sessionRecovery()->autosave();
    QVERIFY2(autosave.lastError().isEmpty(), qPrintable(autosave.lastError()));
    QVERIFY(!autosave.saveNow()); // nothing unsaved
    QVERIFY(!QFile::exists(autosave.recoveryProjectPath()));

    window->designWorkspace()->startNewSet(DynamicRule::ConstructiveSubtractive);
    QVERIFY(window->designWorkspace()->isModified());
    QVERIFY(autosave.saveNow());
    QVERIFY(!autosave.saveNow()); // unchanged since
    const timeline::Project saved = timeline::readProject(autosave.recoveryProjectPath().toStdString());
    QCOMPARE(saved.timeline, window->designWorkspace()->session()->timeline());
    // Nothing of this live window is offered (its lock is held).
    QVERIFY(Autosave::recoverableSessions(recovery).isEmpty());

    QString error;
    QVERIFY2(window->designWorkspace()->projectFiles()->saveTo(path(QStringLiteral("autosaved.trimlab")), &error),
             qPrintable(error));
    QVERIFY(!QFile::exists(autosave.recoveryProjectPath()));
}

void TestSessionRecovery::recoverBringsBackTheHistoryModified()
{
    const QString recovery = path(QStringLiteral("recover-recovery"));
    const QString original = path(QStringLiteral("design.trimlab"));
    writeCrashedSession(recovery, QStringLiteral("session-1"), original);
    auto window = showWindow(QStringLiteral("recover"), recovery);
    QMessageBox* box = waitForOffer(*window);
    QVERIFY(box);
    QVERIFY2(box->informativeText().contains(QStringLiteral("design.trimlab")), qPrintable(box->informativeText()));
    QVERIFY(waitForDefaultScene(*window));
    QVERIFY(recoverAndWait(*window, box));
    const timeline::Timeline expected = crashedHistory();
    QCOMPARE(window->document()->filePath(), original);
    QVERIFY(window->designWorkspace()->isModified());
    QVERIFY(window->isWindowModified());
    QVERIFY2(window->windowTitle().startsWith(QStringLiteral("design.trimlab")), qPrintable(window->windowTitle()));
    QVERIFY(!window->recentFiles().contains(recovery + QStringLiteral("/session-1.trimlab")));
    // The crashed copy is gone; this window's own autosave holds the work now.
    QVERIFY(!QFile::exists(recovery + QStringLiteral("/session-1.trimlab")));
    QVERIFY(!QFile::exists(recovery + QStringLiteral("/session-1.json")));
    const QString own = window->designWorkspace()->sessionRecovery()->autosave().recoveryProjectPath();
    QVERIFY(QFile::exists(own));
    QCOMPARE(timeline::readProject(own.toStdString()).timeline, expected);
}

// Work that was never saved comes back under no name of the recovery folder's files.
void TestSessionRecovery::anUntitledRecoveryShowsNoInternalName()
{
    const QString recovery = path(QStringLiteral("untitled-recovery"));
    writeCrashedSession(recovery, QStringLiteral("session-5"), QString());
    auto window = showWindow(QStringLiteral("untitled"), recovery);
    QMessageBox* box = waitForOffer(*window);
    QVERIFY(box);
    QVERIFY(waitForDefaultScene(*window));
    QVERIFY(recoverAndWait(*window, box));
    QVERIFY(window->isWindowModified());
    QVERIFY2(!window->windowTitle().contains(QStringLiteral("session-")), qPrintable(window->windowTitle()));
    QVERIFY2(window->windowTitle().startsWith(QStringLiteral("Untitled")), qPrintable(window->windowTitle()));
    window->designWorkspace()->sessionRecovery()->autosave().clear();
}

void TestSessionRecovery::discardDeletesTheAutosave()
{
    const QString recovery = path(QStringLiteral("discard-recovery"));
    writeCrashedSession(recovery, QStringLiteral("session-2"), QString());
    auto window = showWindow(QStringLiteral("discard"), recovery);
    QMessageBox* box = waitForOffer(*window);
    QVERIFY(box);
    QVERIFY2(box->informativeText().contains(QStringLiteral("untitled")), qPrintable(box->informativeText()));
    QVERIFY(waitForDefaultScene(*window));
    const timeline::Timeline shown = window->designWorkspace()->session()->timeline();
    QAbstractButton* discard = buttonWithRole(box, QMessageBox::DestructiveRole);
    QVERIFY(discard);
    discard->click();
    QVERIFY(QTest::qWaitFor([&] { return !QFile::exists(recovery + QStringLiteral("/session-2.trimlab")); },
                            test::kWaitMs));
    QVERIFY(!QFile::exists(recovery + QStringLiteral("/session-2.json")));
    QTest::qWait(50);
    QCOMPARE(window->designWorkspace()->session()->timeline(), shown);
    QVERIFY(!window->designWorkspace()->isModified());
    QVERIFY(Autosave::recoverableSessions(recovery).isEmpty());
}

void TestSessionRecovery::liveSessionsAreNeverOffered()
{
    const QString recovery = path(QStringLiteral("live-recovery"));
    writeCrashedSession(recovery, QStringLiteral("session-3"), QString());
    // A running TrimLab holds its lock (here: this process, as another window would).
    QLockFile lock(recovery + QStringLiteral("/session-3.lock"));
    lock.setStaleLockTime(0);
    QVERIFY(lock.tryLock(0));
    QVERIFY(Autosave::recoverableSessions(recovery).isEmpty());
    lock.unlock();
    // Once it is gone, its work is recoverable.
    const QList<RecoverableSession> sessions = Autosave::recoverableSessions(recovery);
    QCOMPARE(sessions.size(), 1);
    QCOMPARE(sessions.front().projectFile, recovery + QStringLiteral("/session-3.trimlab"));
}

QTEST_MAIN(TestSessionRecovery)
#include "tst_session_recovery.moc"
