// The GUI's load paths on the whole malformed-file corpus (tests/data/broken, the tables
// of tests/data/README.md): every broken mesh and project (version 1 and 2) opened with
// File ▸ Open (MainWindow::openSource), every broken animation with Open Animation
// (openAnimation), every broken stroke script replayed on the shown mesh
// (HistoryExports::replay), every broken NURBS file through Create ▸ NURBS ▸ From NURBS
// File (createSurfaceFromNurbsFile) and every broken cage through Create ▸ Subdivision
// Surface ▸ From Cage File (createSurfaceFromCageFile) must report the error the tables
// give — in the error dialog and its signal — and leave the scene, the design session and
// the window as they were. A crash, a hang or a silently accepted file fails. Skeleton
// files have no GUI load path (only core reads them; tst_fuzz_regressions checks them).
#include "design_window.h"
#include "gl_test_context.h"
#include "message_box_closer.h"
#include "test_paths.h"

#include "ui/design/design_session.h"
#include "ui/design/design_workspace.h"
#include "ui/design/history_exports.h"
#include "ui/window/main_window.h"
#include "ui/surface/surface_workspace.h"
#include "ui/surface/surface_panel.h"

#include <QFile>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace trimlab;
using namespace trimlab::ui;

namespace {

constexpr QSize kViewportSize(96, 72);

struct BrokenFile {
    QString name;
    QString phrase; ///< the message contains it
};

// Rows "| `a` `b` | … | phrase |" of the README sections whose heading starts with
// `heading`.
QList<BrokenFile> tableRows(const QString& heading)
{
    QFile readme(QString::fromStdString(test::testDataPath("README.md").string()));
    if (!readme.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    const QStringList lines = QString::fromUtf8(readme.readAll()).split(QLatin1Char('\n'));
    static const QRegularExpression row(QStringLiteral("^\\| (`[^|]+`) \\| [^|]* \\| ([^|]+) \\|$"));
    static const QRegularExpression quoted(QStringLiteral("`([^`]+)`"));
    QList<BrokenFile> files;
    bool inside = false;
    for (const QString& line : lines) {
        if (line.startsWith(QStringLiteral("## ")))
            inside = line.startsWith(heading);
        const QRegularExpressionMatch match = row.match(line);
        if (!inside || !match.hasMatch())
            continue;
        for (auto it = quoted.globalMatch(match.captured(1)); it.hasNext();)
            files.push_back({it.next().captured(1), match.captured(2)});
    }
    return files;
}

QString brokenPath(const QString& name)
{
    return QString::fromStdString(test::testDataPath("broken/" + name.toStdString()).string());
}

} // namespace

class TestGuiBrokenFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyBrokenFileReportsItsErrorAndChangesNothing();

private:
    // Runs `open` and waits for sceneLoadFailed; "" when it never came (or a load succeeded).
    static QString failureOf(MainWindow& window, const std::function<void()>& open);
    static QString replayProblemOf(MainWindow& window, const QString& path);

    QTemporaryDir m_dir;
};

void TestGuiBrokenFiles::initTestCase()
{
    TRIMLAB_INIT_WIDGET_TEST();
    QVERIFY(m_dir.isValid());
}

QString TestGuiBrokenFiles::failureOf(MainWindow& window, const std::function<void()>& open)
{
    QSignalSpy failed(&window, &MainWindow::sceneLoadFailed);
    QSignalSpy loaded(&window, &MainWindow::sceneLoaded);
    QSignalSpy animation(&window, &MainWindow::animationLoaded);
    open();
    if (!QTest::qWaitFor([&] { return !failed.isEmpty() || !loaded.isEmpty() || !animation.isEmpty(); }, test::kWaitMs))
        return {};
    return failed.isEmpty() ? QString() : failed.front().at(1).toString();
}

QString TestGuiBrokenFiles::replayProblemOf(MainWindow& window, const QString& path)
{
    QSignalSpy problem(window.designWorkspace()->historyExports(), &HistoryExports::problem);
    QSignalSpy replayed(window.designWorkspace()->historyExports(), &HistoryExports::replayed);
    window.designWorkspace()->historyExports()->replay(path);
    if (!QTest::qWaitFor([&] { return !problem.isEmpty() || !replayed.isEmpty(); }, test::kWaitMs))
        return {};
    return problem.isEmpty() ? QString() : problem.front().at(2).toString();
}

void TestGuiBrokenFiles::everyBrokenFileReportsItsErrorAndChangesNothing()
{
    const QList<BrokenFile> meshes = tableRows(QStringLiteral("## Broken files"));
    const QList<BrokenFile> documents = tableRows(QStringLiteral("## Broken project files"));
    QVERIFY2(meshes.size() >= 84, qPrintable(QString::number(meshes.size())));
    QVERIFY2(documents.size() >= 82, qPrintable(QString::number(documents.size())));

    test::MessageBoxCloser closer; // the error dialogs, as a user pressing Return
    auto window = test::showDesignWindow(m_dir.filePath(QStringLiteral("broken.ini")), kViewportSize);
    QVERIFY(
        QTest::qWaitFor([&] { return !window->isLoading() && window->designWorkspace()->session(); }, test::kWaitMs));
    const std::string shownSource = window->scene()->source;
    const DesignSession* shownSession = window->designWorkspace()->session();
    const timeline::Timeline shownHistory = shownSession->timeline();
    const QString shownTitle = window->windowTitle();
    // The cage rows' errors assume cages are read for Catmull–Clark (a fresh settings file).
    QVERIFY(window->surfaceWorkspace()->panel()->choices().scheme == SubdivisionScheme::CatmullClark);

    QStringList problems;
    int checked = 0;
    int coreOnly = 0;
    const auto check = [&](const BrokenFile& file, const QString& message) {
        ++checked;
        if (!message.contains(file.phrase))
            problems << QStringLiteral("%1: expected '%2', got '%3'").arg(file.name, file.phrase, message);
        if (window->scene()->source != shownSource || window->designWorkspace()->session() != shownSession ||
            shownSession->timeline() != shownHistory || window->windowTitle() != shownTitle)
            problems << QStringLiteral("%1: the shown scene, session, history or title changed").arg(file.name);
    };
    // The Create menu's file actions report synchronously and return whether they succeeded.
    const auto create = [&](const BrokenFile& file, bool (SurfaceWorkspace::*action)(const QString&)) {
        bool created = true;
        const QString message =
            failureOf(*window, [&] { created = (window->surfaceWorkspace()->*action)(brokenPath(file.name)); });
        if (created)
            problems << QStringLiteral("%1: the surface was created").arg(file.name);
        check(file, message);
    };
    for (const BrokenFile& file : meshes)
        check(file, failureOf(*window, [&] { window->openSource(brokenPath(file.name)); }));
    for (const BrokenFile& file : documents) {
        const QString path = brokenPath(file.name);
        if (file.name.startsWith(QStringLiteral("project_")))
            check(file, failureOf(*window, [&] { window->openSource(path); }));
        else if (file.name.startsWith(QStringLiteral("anim_")))
            check(file, failureOf(*window, [&] { window->openAnimation(path); }));
        else if (file.name.startsWith(QStringLiteral("script_")))
            check(file, replayProblemOf(*window, path));
        else if (file.name.startsWith(QStringLiteral("nurbs_")))
            create(file, &SurfaceWorkspace::createFromNurbsFile);
        else if (file.name.startsWith(QStringLiteral("cage_")))
            create(file, &SurfaceWorkspace::createFromCageFile);
        else if (file.name.startsWith(QStringLiteral("skeleton_")))
            ++coreOnly;
        else
            problems << QStringLiteral("%1: no GUI load path known for this file").arg(file.name);
    }
    qInfo("%d broken files through the GUI (%d skeleton files checked in core only), %lld dialogs closed", checked,
          coreOnly, qlonglong(closer.seen().size()));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    QCOMPARE(checked + coreOnly, int(meshes.size() + documents.size()));
}

QTEST_MAIN(TestGuiBrokenFiles)
#include "tst_gui_broken_files.moc"
